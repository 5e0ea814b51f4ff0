// ESLint for the page's JavaScript (web/) and its browser tests (tests/web/): the rules of
// ESLint's "recommended" set that find mistakes, written out so that this file needs no package
// beside ESLint itself (tests/web/package.json). Run: bash scripts/lint.sh.
const browser = {
  window: 'readonly', document: 'readonly', location: 'readonly', history: 'readonly', navigator: 'readonly', console: 'readonly',
  URLSearchParams: 'readonly', URL: 'readonly', Blob: 'readonly', Worker: 'readonly', self: 'readonly', setTimeout: 'readonly',
  clearTimeout: 'readonly', requestAnimationFrame: 'readonly', cancelAnimationFrame: 'readonly', performance: 'readonly',
  Event: 'readonly', getComputedStyle: 'readonly', XMLSerializer: 'readonly', DOMParser: 'readonly', matchMedia: 'readonly',
};
const node = { process: 'readonly', console: 'readonly', Buffer: 'readonly', setTimeout: 'readonly', URL: 'readonly' };
const mistakes = {
  'no-undef': 'error', 'no-unused-vars': ['error', { args: 'none', caughtErrors: 'none' }], 'no-redeclare': 'error', 'no-dupe-keys': 'error',
  'no-dupe-args': 'error', 'no-duplicate-case': 'error', 'no-unreachable': 'error', 'no-self-assign': 'error', 'no-self-compare': 'error',
  'no-const-assign': 'error', 'no-func-assign': 'error', 'no-cond-assign': 'error', 'no-constant-condition': ['error', { checkLoops: false }],
  'no-empty': ['error', { allowEmptyCatch: true }], 'no-fallthrough': 'error', 'no-unsafe-finally': 'error', 'no-unsafe-negation': 'error',
  'use-isnan': 'error', 'valid-typeof': 'error', 'no-sparse-arrays': 'error', 'no-loss-of-precision': 'error', 'no-shadow-restricted-names': 'error',
  'no-use-before-define': ['error', { functions: false, classes: true, variables: false }], eqeqeq: ['error', 'smart'], 'no-var': 'error',
  'prefer-const': 'error',
};
export default [
  {
    files: ['web/app.js', 'web/viewer.js'],
    languageOptions: { ecmaVersion: 2022, sourceType: 'script', globals: { ...browser, createTrebuchet: 'readonly', TrebuchetViewer: 'writable' } },
    rules: mistakes,
  },
  {
    files: ['web/*.mjs', 'tests/web/*.mjs'],
    languageOptions: { ecmaVersion: 2022, sourceType: 'module', globals: { ...node, ...browser } },
    rules: mistakes,
  },
];
