// Puts the page into one file: web/index.html with style.css, qrcode-generator (npm), the module
// (trebuchet.js, its WebAssembly inside), viewer.js and app.js inlined, so that it opens from file:// and fetches
// nothing.   node web/bundle.mjs MODULE.js OUT.html
import { readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const [modulePath, outPath] = process.argv.slice(2);
if (!modulePath || !outPath) {
  console.error('usage: node web/bundle.mjs build-web/web/trebuchet.js build-web/trebuchet.html');
  process.exit(2);
}
const here = dirname(fileURLToPath(import.meta.url));
const read = (path) => readFileSync(path, 'utf8');
// Text inside <script> must not close it early.
const script = (code, id) => `<script${id ? ` id="${id}"` : ''}>\n${code.replace(/<\/script/gi, '<\\/script')}\n</script>`;
// The QR code library, from npm (web/package.json, installed by scripts/install-deps.sh).
const qrcodePath = join(here, 'node_modules', 'qrcode-generator', 'dist', 'qrcode.js');
const parts = {
  '<!-- qrcode -->': script(read(qrcodePath)),
  '<!-- style -->': `<style>\n${read(join(here, 'style.css'))}</style>`,
  '<!-- module -->': script(read(modulePath), 'trebuchet-module'),
  '<!-- viewer -->': script(read(join(here, 'viewer.js'))),
  '<!-- app -->': script(read(join(here, 'app.js'))),
};
let page = read(join(here, 'index.html'));
for (const [mark, text] of Object.entries(parts)) {
  if (!page.includes(mark)) throw new Error(`web/index.html lacks ${mark}`);
  page = page.replace(mark, () => text);
}
writeFileSync(outPath, page);
console.log(`${outPath}: ${(Buffer.byteLength(page) / 1e6).toFixed(2)} MB`);
