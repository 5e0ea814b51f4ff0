// How tests/test_sling.cpp's Trebuchator figures were made (issue 48): Trebuchator's backyard,
// simple-fixed and floating-arm presets, with its drag and friction turned off, released at its
// range optimum. Not run by CTest: it needs Trebuchator's source (jonjaques/trebuchator), which is
// not ours to ship. Run from a checkout of it, with tsx (npm):
//   npx tsx path/to/trebuchator_presets.ts
// and each line gives the preset, its release time [s] and its range [m] from the pivot (the
// floating arm's: from its guide's line) to the ground, 5 cm below its trough.
import { simulateShot } from './src/lib/treb/simulate.ts'
import { PRESETS } from './src/lib/treb/presets.ts'

for (const id of ['backyard', 'simple-fixed', 'floating-arm']) {
  const preset = PRESETS.find((p) => p.id === id)
  if (!preset) throw new Error(`no preset ${id}`)
  const p = { ...preset.params, releaseMode: 'optimal' as const, enableDrag: false, pivotFriction: 0, hingeFriction: 0, troughFriction: 0 }
  const shot = simulateShot(p)
  console.log(JSON.stringify({ id, slingMass: p.slingMass, t_release: shot.release?.t, range: shot.range }))
}
