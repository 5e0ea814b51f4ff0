import { launch, open } from './browser.mjs';
const b = await launch();
const url = 'file:///work/main/build-web/trebuchet.html';
for (const [name, vp, hash] of [['design', {width:1280,height:800}, ''], ['phone', {width:390,height:844}, '']]) {
  const { page, problems, requests } = await open(b, url + hash, vp);
  await page.waitForTimeout(300);
  await page.screenshot({ path: `/tmp/page-${name}.png`, fullPage: true });
  console.log(name, problems, requests);
}
await b.close();
