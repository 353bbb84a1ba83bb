// convexloc's web page: the Emscripten module's settings, the viewer's command line from the
// page's URL, the loading bar, the message box every problem reaches, and the file picker.
// The viewer itself (convexloc-viewer.js) is loaded by this script once WebGL 2 is known.
'use strict';

// The viewer's options from the URL: ?figure=6&step=2 is --figure 6 --step 2, a key without
// a value a switch (?3d); ?lecture=NAME is the shipped lecture NAME (assets/lectures/), and
// ?lecture=URL a lecture of one's own beside the page (fetched with its shapes: lectures.js).
function convexlocArguments(search, pixelRatio) {
  const args = [];
  let fontScaleGiven = false;
  for (const [key, value] of new URLSearchParams(search)) {
    if (!/^[a-z0-9][a-z0-9-]*$/.test(key)) {
      convexlocProblem('The link\'s "' + key + '" is not an option of the viewer: left out.');
      continue;
    }
    let v = value;
    if (key === 'lecture' && /^[A-Za-z0-9_-]+$/.test(v)) v = '/assets/lectures/' + v + '.lecture';
    else if (key === 'lecture') v = convexlocLecturePath(v);
    if (key === 'font-scale') fontScaleGiven = true;
    args.push('--' + key);
    if (v !== '') args.push(v);
  }
  // a HiDPI screen: the canvas has all its pixels, the panels' text keeps its size on the
  // screen (a slide's grows with its page already)
  if (!fontScaleGiven && pixelRatio > 1) args.push('--ui-scale', pixelRatio.toFixed(2));
  return args;
}

const convexlocStatus = document.getElementById('status');
const convexlocBar = document.getElementById('progress');

// === The message box: every problem, from the URL, the viewer, the browser or a crash
function convexlocProblem(text) {
  const box = document.getElementById('problems');
  const list = document.getElementById('problem-list');
  if ([...list.children].some((li) => li.textContent === text)) return;
  const li = document.createElement('li');
  li.textContent = text;
  list.appendChild(li);
  box.hidden = false;
}
document.getElementById('problems-close').addEventListener('click', () => {
  document.getElementById('problems').hidden = true;
  document.getElementById('problem-list').replaceChildren();
});
window.addEventListener('error', (e) => convexlocProblem(
    'The page hit an error: ' + (e.message || e) + '. Reloading the page starts it again.'));
window.addEventListener('unhandledrejection', (e) => convexlocProblem(
    'The page hit an error: ' + (e.reason && e.reason.message || e.reason) +
    '. Reloading the page starts it again.'));

// What the browser lacks when it gives no WebGL 2 context (null: it gives one)
function convexlocWebGl2Missing() {
  try {
    if (document.createElement('canvas').getContext('webgl2')) return null;
  } catch (e) {
    // a browser that throws lacks it as much as one that says no
  }
  return 'This browser gives the page no WebGL 2, which the viewer draws with' +
         (window.WebGL2RenderingContext ? ' (it knows WebGL 2, but turned it off or cannot' +
          ' use the graphics card)' : '') + '. Try a recent Firefox, Chrome, Edge or Safari' +
         ' (version 15 or later), turn the browser\'s hardware acceleration on, or update the' +
         ' graphics driver, then open the page again.';
}

// === Loading: one bar over the .data file (Emscripten's own count) and the .wasm (ours)
const convexlocLoad = {data: [0, 0], wasm: [0, 0]};

function convexlocShowLoad() {
  const done = convexlocLoad.data[0] + convexlocLoad.wasm[0];
  const total = convexlocLoad.data[1] + convexlocLoad.wasm[1];
  if (total > 0) convexlocBar.value = Math.min(1, done / total);
  const ready = convexlocLoad.wasm[1] > 0 && convexlocLoad.wasm[0] >= convexlocLoad.wasm[1];
  convexlocStatus.textContent =
      ready && done >= total ? 'Starting convexloc…' : 'Loading convexloc…';
}

// the .wasm fetched with its progress counted, then compiled (instead of Emscripten's fetch)
async function convexlocFetchWasm(imports, done) {
  const response = await fetch('convexloc-viewer.wasm');
  if (!response.ok) throw new Error('convexloc-viewer.wasm: HTTP ' + response.status);
  convexlocLoad.wasm[1] = Number(response.headers.get('Content-Length')) || 1;
  const parts = [];
  const reader = response.body.getReader();
  for (let r = await reader.read(); !r.done; r = await reader.read()) {
    parts.push(r.value);
    convexlocLoad.wasm[0] += r.value.length;
    convexlocShowLoad();
  }
  convexlocLoad.wasm[0] = convexlocLoad.wasm[1] = Math.max(convexlocLoad.wasm[0], 1);
  convexlocShowLoad();
  const result = await WebAssembly.instantiate(await new Blob(parts).arrayBuffer(), imports);
  done(result.instance, result.module);
}

var Module = {
  canvas: document.getElementById('canvas'),
  arguments: [],
  print: (text) => console.log(text),
  printErr: (text) => console.warn(text),
  framesDrawn: 0,
  firstFrameMs: null,  // milliseconds from the page's start to the first frame drawn
  downloads: [],       // the files offered as downloads: [name, bytes]
  view: null,          // the view's state after each frame (platform/page.cpp)
  pointerOverUi: false,
  setStatus: (text) => {
    const m = /\((\d+)\/(\d+)\)/.exec(text || '');
    if (m) convexlocLoad.data = [Number(m[1]), Number(m[2])];
    convexlocShowLoad();
  },
  instantiateWasm: (imports, done) => {
    convexlocFetchWasm(imports, done).catch((e) => convexlocProblem(
        'The viewer could not be loaded: ' + e.message + '. Reloading the page tries again.'));
    return {};
  },
  preRun: [() => convexlocFetchLectures()],
  onRuntimeInitialized: () => convexlocOpenWaiting(),
  onFrame: () => {
    document.body.classList.toggle('drawer-open', !!(Module.view && Module.view.drawerOpen));
    if (++Module.framesDrawn > 1) return;
    Module.firstFrameMs = performance.now();
    document.getElementById('loading').remove();
  },
  onDownload: (name, bytes) => Module.downloads.push([name, bytes]),
  onProblem: (text) => convexlocProblem(text),
  onAbort: (what) => {
    Module.stopped = true;
    convexlocProblem('The viewer stopped: ' + what + '. Reloading the page starts it again.');
  },
};

// === Files from the picker or dropped: written into the page's in-memory files and opened
// at the viewer's next frame; files chosen while the page loads wait for the viewer
let convexlocWaiting = [];

async function convexlocOpenFiles(files) {
  if (!Module.calledRun) {
    convexlocWaiting.push(...files);
    return;
  }
  const path = await convexlocWriteFiles(files, '/uploads');
  if (path) Module.ccall('convexloc_open_file', null, ['string'], [path]);
}

function convexlocOpenWaiting() {
  const files = convexlocWaiting;
  convexlocWaiting = [];
  if (files.length) setTimeout(() => convexlocOpenFiles(files), 0);
}

document.getElementById('file').addEventListener('change', async (event) => {
  const files = [...event.target.files];
  event.target.value = '';
  Module.canvas.focus();
  await convexlocOpenFiles(files);
});

// start: the viewer where WebGL 2 is there, else the reason in the message box
(() => {
  const missing = convexlocWebGl2Missing();
  if (missing) {
    document.getElementById('loading').remove();
    convexlocProblem(missing);
    return;
  }
  Module.arguments = convexlocArguments(window.location.search, window.devicePixelRatio || 1);
  const script = document.createElement('script');
  script.src = 'convexloc-viewer.js';
  script.async = true;
  document.body.appendChild(script);
})();
