// convexloc's web page: the user's own files. Files picked or dropped (several at once: a
// lecture with the shape files it names) are written into the page's in-memory files and
// open at the viewer's next frame; ?lecture=URL fetches a lecture and the files it names,
// relative to it, from the web server before the viewer starts. Loaded before page.js.
'use strict';

// a lecture's lines that name a file (relative to the lecture): `shape F`, `why-from F`
const convexlocFileKey = /^\s*(?:shape|why-from)\s+(?:"([^"]*)"|(\S+))/;

// the files a lecture's text names, as written
function convexlocNamedFiles(text) {
  const named = [];
  for (const line of text.split('\n')) {
    const m = convexlocFileKey.exec(line);
    if (m) named.push(m[1] !== undefined ? m[1] : m[2]);
  }
  return named;
}

// `path` without its "." and ".." parts ("/a/b/../c" is "/a/c")
function convexlocNormal(path) {
  const parts = [];
  for (const p of path.split('/')) {
    if (p === '..') parts.pop();
    else if (p !== '.' && p !== '') parts.push(p);
  }
  return '/' + parts.join('/');
}

function convexlocWrite(path, bytes) {
  Module.FS.mkdirTree(path.slice(0, path.lastIndexOf('/')) || '/');
  Module.FS.writeFile(path, bytes);
}

let convexlocUploads = 0;

// Writes the chosen files into a folder of their own under `root` and returns the path to
// open: the lecture among them, its named files placed where it names them (matched by file
// name), else the last file.
async function convexlocWriteFiles(files, root) {
  if (!files.length) return null;
  const base = root + '/' + (++convexlocUploads);
  const lecture = files.find((f) => /\.lecture$/i.test(f.name));
  if (!lecture) {
    for (const f of files)
      convexlocWrite(base + '/' + f.name, new Uint8Array(await f.arrayBuffer()));
    return base + '/' + files[files.length - 1].name;
  }
  const text = await lecture.text();
  const named = convexlocNamedFiles(text);
  // the lecture deep enough that its "../" names stay inside the folder
  const depth = Math.max(0, ...named.map((n) => (n.match(/\.\.\//g) || []).length));
  const dir = base + '/l'.repeat(depth);
  convexlocWrite(dir + '/' + lecture.name, new TextEncoder().encode(text));
  const missing = [];
  for (const name of named) {
    const leaf = name.slice(name.lastIndexOf('/') + 1);
    const file = files.find((f) => f.name === leaf);
    if (file)
      convexlocWrite(convexlocNormal(dir + '/' + name), new Uint8Array(await file.arrayBuffer()));
    else if (!name.startsWith('/')) missing.push(name);
  }
  if (missing.length)
    convexlocProblem(lecture.name + ' names ' + missing.join(', ') + ', which ' +
                     (missing.length > 1 ? 'were' : 'was') + ' not among the files chosen: ' +
                     'choose them together with the lecture (or drop them all at once).');
  return dir + '/' + lecture.name;
}

// === ?lecture=URL: where the lecture will be in the page's files; it and its named files
// are fetched before the viewer starts (a failure is said, and the lecture left out)
const convexlocRemote = [];

function convexlocLecturePath(value) {
  const url = new URL(value, window.location.href);
  const path = convexlocNormal('/web/' + url.host + url.pathname);
  convexlocRemote.push({url: url, path: path});
  return path;
}

async function convexlocFetch(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(url + ': HTTP ' + response.status + ' ' + response.statusText);
  return new Uint8Array(await response.arrayBuffer());
}

async function convexlocFetchLecture(remote) {
  const bytes = await convexlocFetch(remote.url);
  convexlocWrite(remote.path, bytes);
  const dir = remote.path.slice(0, remote.path.lastIndexOf('/'));
  for (const name of convexlocNamedFiles(new TextDecoder().decode(bytes))) {
    if (name.startsWith('/')) continue;
    try {
      const bytes = await convexlocFetch(new URL(name, remote.url));
      convexlocWrite(convexlocNormal(dir + '/' + name), bytes);
    } catch (e) {
      convexlocProblem('The lecture ' + remote.url + ' names ' + name + ', which could not be ' +
                       'fetched (' + e.message + '): its slides show what they can without it.');
    }
  }
}

function convexlocFetchLectures() {
  for (const remote of convexlocRemote) {
    Module.addRunDependency('lecture ' + remote.url);
    convexlocFetchLecture(remote).catch((e) => {
      convexlocProblem('The lecture ' + remote.url + ' could not be fetched (' + e.message +
                       '): the page opens without it. Is it on the same server as the page?');
      const at = Module.arguments.indexOf(remote.path);
      if (at > 0) Module.arguments.splice(at - 1, 2);
    }).finally(() => Module.removeRunDependency('lecture ' + remote.url));
  }
}

// files dropped on the page: as picked (Emscripten's own drop would open them one by one)
window.addEventListener('drop', (e) => {
  if (!e.dataTransfer || !e.dataTransfer.files || !e.dataTransfer.files.length) return;
  e.preventDefault();
  e.stopPropagation();
  convexlocOpenFiles([...e.dataTransfer.files]);
}, {capture: true});
window.addEventListener('dragover', (e) => e.preventDefault());
