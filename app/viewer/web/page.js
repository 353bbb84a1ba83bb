// convexloc's web page: the Emscripten module's settings, the viewer's command line from the
// page's URL, and the file picker. The viewer itself (convexloc-viewer.js) loads after this.
'use strict';

// The viewer's options from the URL: ?figure=6&step=2 is --figure 6 --step 2, a key without
// a value a switch (?3d), and ?lecture=NAME the shipped lecture NAME (assets/lectures/).
function convexlocArguments(search, pixelRatio) {
  const args = [];
  let fontScaleGiven = false;
  for (const [key, value] of new URLSearchParams(search)) {
    if (!/^[a-z0-9][a-z0-9-]*$/.test(key)) continue;
    let v = value;
    if (key === 'lecture' && /^[A-Za-z0-9_-]+$/.test(v)) v = '/assets/lectures/' + v + '.lecture';
    if (key === 'font-scale') fontScaleGiven = true;
    args.push('--' + key);
    if (v !== '') args.push(v);
  }
  // a HiDPI screen: the canvas has all its pixels, the text keeps its size on the screen
  if (!fontScaleGiven && pixelRatio > 1) args.push('--font-scale', pixelRatio.toFixed(2));
  return args;
}

const convexlocStatus = document.getElementById('status');

var Module = {
  canvas: document.getElementById('canvas'),
  arguments: convexlocArguments(window.location.search, window.devicePixelRatio || 1),
  print: (text) => console.log(text),
  printErr: (text) => console.warn(text),
  framesDrawn: 0,
  firstFrameMs: null,  // milliseconds from the page's start to the first frame drawn
  downloads: [],       // the files offered as downloads: [name, bytes]
  setStatus: (text) => {
    if (text) convexlocStatus.textContent = text;
  },
  onFrame: () => {
    if (++Module.framesDrawn > 1) return;
    Module.firstFrameMs = performance.now();
    convexlocStatus.remove();
  },
  onDownload: (name, bytes) => Module.downloads.push([name, bytes]),
  onAbort: (what) => {
    convexlocStatus.textContent = 'convexloc stopped: ' + what;
  },
};

// The file picker: the chosen file goes into the page's in-memory files and the viewer
// opens it at its next frame, as it does a file dropped on the canvas.
document.getElementById('file').addEventListener('change', async (event) => {
  const file = event.target.files[0];
  if (!file || !Module.calledRun) return;
  const data = new Uint8Array(await file.arrayBuffer());
  const path = '/uploads/' + file.name.replace(/\//g, '_');
  Module.FS.mkdirTree('/uploads');
  Module.FS.writeFile(path, data);
  Module.ccall('convexloc_open_file', null, ['string'], [path]);
  event.target.value = '';
  Module.canvas.focus();
});
