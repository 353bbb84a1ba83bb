"""The page's test harness: a static server for build-web/site/, Debian's Chromium headless
(software WebGL 2 through SwiftShader) driven over the DevTools protocol with
python3-websocket, and a PNG decoder for its screenshots (zlib only, no imaging library)."""

import base64
import functools
import http.server
import json
import os
import shutil
import struct
import subprocess
import tempfile
import threading
import time
import urllib.request
import zlib

import websocket


class Server:
    """Serves `root` on 127.0.0.1 at a free port, in a thread; `extra` ({"own": DIR}) serves
    DIR's files at /own/ too."""

    def __init__(self, root, extra=None):
        handler = functools.partial(_QuietHandler, directory=root)
        _QuietHandler.extra = dict(extra or {})
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.url = "http://127.0.0.1:%d/" % self.httpd.server_address[1]
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)
        self.thread.start()

    def close(self):
        self.httpd.shutdown()
        self.httpd.server_close()


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map,
                      ".wasm": "application/wasm", ".js": "text/javascript"}

    extra = {}

    def translate_path(self, path):
        first, _, rest = path.lstrip("/").partition("/")
        if first in self.extra:
            return os.path.join(self.extra[first], *rest.split("?")[0].split("/"))
        return super().translate_path(path)

    def log_message(self, *args):
        pass


class Browser:
    """One headless Chromium with one page, and the console errors that page has shown."""

    def __init__(self, width=1280, height=800):
        self.profile = tempfile.mkdtemp(prefix="convexloc-chromium-")
        self.proc = subprocess.Popen(
            ["chromium", "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--remote-debugging-port=0",
             "--user-data-dir=" + self.profile, "--window-size=%d,%d" % (width, height),
             "--no-first-run", "--no-default-browser-check", "--disable-extensions",
             "--hide-scrollbars", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.port = self._port()
        with urllib.request.urlopen("http://127.0.0.1:%d/json/list" % self.port) as r:
            targets = json.load(r)
        self.next_id = 0
        self.errors = []
        self.console = []
        self._attach(next(t for t in targets if t["type"] == "page"))
        self.call("Emulation.setDeviceMetricsOverride", width=width, height=height,
                  deviceScaleFactor=1, mobile=False)

    def _attach(self, page):
        self.page_id = page["id"]
        self.ws = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=60)
        for domain in ("Page", "Runtime", "Log"):
            self.call(domain + ".enable")

    def new_page(self):
        """This page closed and a new blank one in its place (its emulation not set)."""
        new = urllib.request.Request("http://127.0.0.1:%d/json/new?about:blank" % self.port,
                                     method="PUT")
        with urllib.request.urlopen(new) as r:
            page = json.load(r)
        old = self.page_id
        self.ws.close()
        self._attach(page)
        urllib.request.urlopen("http://127.0.0.1:%d/json/close/%s" % (self.port, old)).close()

    def _port(self):
        path = os.path.join(self.profile, "DevToolsActivePort")
        deadline = time.time() + 30
        while time.time() < deadline:
            if os.path.exists(path):
                with open(path) as f:
                    first = f.readline().strip()
                if first:
                    return int(first)
            if self.proc.poll() is not None:
                raise RuntimeError("chromium exited with %d" % self.proc.returncode)
            time.sleep(0.1)
        raise RuntimeError("chromium gave no DevTools port in 30 s")

    def call(self, method, **params):
        """Sends one command and returns its result, taking the events that come first."""
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == self.next_id:
                if "error" in msg:
                    raise RuntimeError("%s: %s" % (method, msg["error"]))
                return msg.get("result", {})
            self._event(msg)

    def _event(self, msg):
        method, params = msg.get("method"), msg.get("params", {})
        if method == "Runtime.consoleAPICalled":
            text = " ".join(str(a.get("value", a.get("description", ""))) for a in params["args"])
            self.console.append((params["type"], text))
            if params["type"] in ("error", "assert"):
                self.errors.append("console.error: " + text)
        elif method == "Runtime.exceptionThrown":
            d = params["exceptionDetails"]
            self.errors.append("exception: %s %s" % (
                d.get("text", ""), d.get("exception", {}).get("description", "")))
        elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
            e = params["entry"]
            self.errors.append("log: %s %s" % (e.get("text", ""), e.get("url", "")))

    def evaluate(self, expression, await_promise=False):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True,
                      awaitPromise=await_promise)
        if "exceptionDetails" in r:
            raise RuntimeError("%s: %s" % (expression, r["exceptionDetails"]))
        return r["result"].get("value")

    def wait_for(self, expression, seconds=20.0):
        """Polls until `expression` is truthy; returns the seconds it took."""
        start = time.time()
        while time.time() - start < seconds:
            if self.evaluate(expression):
                return time.time() - start
            time.sleep(0.05)
        raise AssertionError("not true after %.0f s: %s" % (seconds, expression))

    def frames(self):
        return self.evaluate("typeof Module === 'object' ? Module.framesDrawn || 0 : 0")

    def settle(self, frames=4):
        """Waits until the viewer has drawn `frames` more frames."""
        n = self.frames()
        self.wait_for("Module.framesDrawn >= %d" % (n + frames))

    def open(self, url):
        self.call("Page.navigate", url=url)
        self.wait_for("typeof Module === 'object' && Module.framesDrawn >= 3", 30)

    def screenshot(self):
        data = self.call("Page.captureScreenshot", format="png")["data"]
        return decode_png(base64.b64decode(data))

    def click(self, x, y):
        for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
            self.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left",
                      clickCount=1 if kind != "mouseMoved" else 0)

    def key(self, key, code, keycode):
        for kind in ("rawKeyDown", "keyUp"):
            self.call("Input.dispatchKeyEvent", type=kind, key=key, code=code,
                      windowsVirtualKeyCode=keycode, nativeVirtualKeyCode=keycode)

    def close(self):
        try:
            self.ws.close()
        finally:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
            shutil.rmtree(self.profile, ignore_errors=True)


class Image:
    """RGB pixels, top row first."""

    def __init__(self, width, height, rgb):
        self.width, self.height, self.rgb = width, height, rgb

    def pixel(self, x, y):
        i = (y * self.width + x) * 3
        return tuple(self.rgb[i:i + 3])

    def region(self, x0, y0, x1, y1):
        return [self.pixel(x, y) for y in range(y0, y1) for x in range(x0, x1)]


def decode_png(data):
    """An 8-bit RGB or RGBA, non-interlaced PNG's pixels as an Image (alpha dropped)."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError("PNG kind not handled: depth %d colour %d" % (depth, colour))
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    out = bytearray(height * stride)
    prev = bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        _unfilter(f, line, prev, bpp)
        out[y * stride:(y + 1) * stride] = line
        prev = line
    if bpp == 4:
        rgb = bytearray(width * height * 3)
        rgb[0::3], rgb[1::3], rgb[2::3] = out[0::4], out[1::4], out[2::4]
        out = rgb
    return Image(width, height, bytes(out))


def _unfilter(f, line, prev, bpp):
    if f == 0:
        return
    n = len(line)
    if f == 2:
        for i in range(n):
            line[i] = (line[i] + prev[i]) & 255
        return
    for i in range(n):
        a = line[i - bpp] if i >= bpp else 0
        b = prev[i]
        if f == 1:
            line[i] = (line[i] + a) & 255
        elif f == 3:
            line[i] = (line[i] + ((a + b) >> 1)) & 255
        elif f == 4:
            c = prev[i - bpp] if i >= bpp else 0
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        else:
            raise ValueError("bad PNG filter %d" % f)


def changed_pixels(a, b, box=None):
    """How many pixels differ between two screenshots of one size (inside box if given)."""
    x0, y0, x1, y1 = box or (0, 0, a.width, a.height)
    count = 0
    for y in range(y0, y1):
        i, j = (y * a.width + x0) * 3, (y * a.width + x1) * 3
        ra, rb = a.rgb[i:j], b.rgb[i:j]
        if ra != rb:
            count += sum(1 for k in range(0, j - i, 3) if ra[k:k + 3] != rb[k:k + 3])
    return count
