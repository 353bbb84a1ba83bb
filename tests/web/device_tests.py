"""The web page on the devices students have, over the DevTools protocol: a mouse wheel and a
touchpad (deltaMode pixels, lines and pages, both signs, small and large deltas), a phone's
touch (drags, pinches, taps, at 390x844 with the page's own scale staying 1), the message box
for a bad link or a browser without WebGL 2, and a lecture of one's own opened by the file
picker and by ?lecture=URL. The checks read the view's state the page keeps after each frame
(Module.view: the cameras, the left panel's scroll, the lecture's slide)."""

import os
import tempfile
import time

MOBILE = (390, 844)


def view(b):
    return b.evaluate("Module.view")


def wheel(b, x, y, dy, dx=0, ctrl=False):
    """A wheel event as Chromium sends it (deltaMode 0: pixels), then a frame."""
    b.call("Input.dispatchMouseEvent", type="mouseWheel", x=x, y=y, deltaX=dx, deltaY=dy,
           modifiers=2 if ctrl else 0)


def wheel_in(b, x, y, dy, mode):
    """A wheel event in lines (1) or pages (2), which Chromium itself never sends: made in
    the page, as Firefox sends them."""
    b.evaluate("""Module.canvas.dispatchEvent(new WheelEvent('wheel', {clientX: %d, clientY: %d,
               deltaY: %f, deltaMode: %d, bubbles: true, cancelable: true}))""" % (x, y, dy, mode))


def calm(b):
    """Waits out the first 1.5 s after the page's first frame, when a new layout may still
    fit the scene again (ui/frame.cpp's refitOnNewRoom)."""
    b.wait_for("performance.now() > Module.firstFrameMs + 1700")
    b.settle(2)


def settled(b, frames=3):
    b.settle(frames)
    return view(b)


def test_wheel(b, url, check):
    b.open(url + "?3d")
    d0 = settled(b)["distance"]
    wheel(b, 640, 420, -100)
    d1 = settled(b)["distance"]
    check(0.70 <= d1 / d0 <= 0.95, "a wheel notch up (deltaY -100) zooms the 3D scene in by "
          "5-30%% (distance x%.3f)" % (d1 / d0))
    wheel(b, 640, 420, 100)
    d2 = settled(b)["distance"]
    check(abs(d2 / d0 - 1.0) < 1e-6, "a notch down zooms out by as much (x%.3f)" % (d2 / d1))
    wheel_in(b, 640, 420, -3, 1)
    d3 = settled(b)["distance"]
    check(abs(d3 / d1 - 1.0) < 1e-6, "3 lines up (deltaMode 1) are one notch (x%.3f)" % (d3 / d2))
    wheel_in(b, 640, 420, 1, 2)
    d4 = settled(b)["distance"]
    check(abs(d4 / d0 - 1.0) < 1e-6, "a page down (deltaMode 2) is one notch (x%.3f)" % (d4 / d3))
    wheel(b, 640, 420, 5000)
    d5 = settled(b)["distance"]
    check(1.0 < d5 / d4 <= 1.2 ** 3 + 1e-9,
          "a huge delta zooms at most 3 notches (x%.3f)" % (d5 / d4))

    b.open(url)
    s0 = settled(b)["scale2d"]
    wheel(b, 700, 300, -100)
    s1 = settled(b)["scale2d"]
    check(1.05 <= s1 / s0 <= 1.3, "a notch up zooms the 2D scene in (scale x%.3f)" % (s1 / s0))
    for _ in range(10):
        wheel(b, 700, 300, -4, ctrl=True)  # a touchpad's pinch: small deltas with Ctrl
    s2 = settled(b)["scale2d"]
    check(s2 > s1 * 1.05 and b.evaluate("visualViewport.scale") == 1,
          "a touchpad pinch (Ctrl wheel) zooms the scene (x%.3f), not the page" % (s2 / s1))


def test_panel_wheel(b, url, check):
    # at 1366x625 the left panel does not fit: the wheel must scroll it a few lines a notch
    b.call("Emulation.setDeviceMetricsOverride", width=1366, height=625, deviceScaleFactor=1,
           mobile=False)
    b.open(url)
    v = settled(b)
    check(v["panelScrollMax"] > 100, "the left panel is taller than 1366x625 (%d px more)" %
          v["panelScrollMax"])
    wheel(b, 120, 300, 100)
    one = settled(b)["panelScroll"]
    check(20 <= one <= 150 and one < v["panelScrollMax"],
          "a notch down scrolls the panel a few lines (%d px of %d)" % (one, v["panelScrollMax"]))
    for _ in range(20):
        wheel(b, 120, 300, 5)
    b.settle(3)
    many = view(b)["panelScroll"]
    check(many > one + 20, "20 touchpad deltas of 5 px scroll it on (%d -> %d px)" % (one, many))
    scale = view(b)["scale2d"]
    wheel(b, 120, 300, -100)
    back = settled(b)
    check(back["panelScroll"] < many and back["scale2d"] == scale,
          "a notch up scrolls back (%d px), the scene unzoomed" % back["panelScroll"])
    wheel(b, 120, 300, -20, ctrl=True)
    pinched = settled(b)
    check(pinched["scale2d"] > scale and pinched["panelScroll"] == back["panelScroll"],
          "a pinch over the panel zooms the scene, the panel stays")


# === Touch on a phone


def touch(b, kind, points, at=None):
    """Touch points (x, y) down, moved or (none) lifted; `at`: the event's time (s)."""
    extra = {"timestamp": at} if at is not None else {}
    b.call("Input.dispatchTouchEvent", type=kind,
           touchPoints=[{"x": x, "y": y, "id": i} for i, (x, y) in enumerate(points)], **extra)


def drag(b, points_from, points_to, steps=8):
    """Fingers down at points_from, moved in steps (a frame each) to points_to, lifted. One
    finger moves at once, as a real one does: a pause first, on a page slow to draw, would be
    a long press."""
    touch(b, "touchStart", points_from)
    if len(points_from) > 1:
        b.settle(2)
    for k in range(1, steps + 1):
        t = k / steps
        touch(b, "touchMove", [(a[0] + (c[0] - a[0]) * t, a[1] + (c[1] - a[1]) * t)
                               for a, c in zip(points_from, points_to)])
        b.settle(1)
    touch(b, "touchEnd", [])
    b.settle(2)


def tap(b, x, y):
    touch(b, "touchStart", [(x, y)])
    touch(b, "touchEnd", [])
    b.settle(3)


def phone(b, url=None):
    """A new page on a 390x844 phone's screen at pixel ratio 2, with touch; then `url`
    opened. (A new page each time: Chromium's touch emulation delivered no touches to a page
    navigated to after touch gestures on the one before, and pinched the page instead.)"""
    b.new_page()
    b.call("Emulation.setDeviceMetricsOverride", width=MOBILE[0], height=MOBILE[1],
           deviceScaleFactor=2, mobile=True)
    b.call("Emulation.setTouchEmulationEnabled", enabled=True, maxTouchPoints=5)
    if url:
        b.open(url)
        calm(b)


def desktop(b, width, height):
    b.new_page()
    b.call("Emulation.setDeviceMetricsOverride", width=width, height=height,
           deviceScaleFactor=1, mobile=False)


def scene_point(b):
    """A CSS point in the scene's middle on the phone (right of any panel)."""
    return (MOBILE[0] * 0.6, MOBILE[1] * 0.55)


def test_touch(b, url, check):
    # (3D first, each page's pinch before its drag: Chromium's touch emulation delivered
    # nothing to a 3D page opened after the 2D one's gestures)
    phone(b, url + "?3d")
    x, y = scene_point(b)
    v0 = view(b)
    drag(b, [(x - 60, y), (x + 60, y)], [(x - 30, y), (x + 30, y)])
    v1 = view(b)
    check(v1["distance"] > v0["distance"] * 1.3,
          "a two-finger pinch zooms the 3D scene out (distance x%.2f)" %
          (v1["distance"] / v0["distance"]))
    drag(b, [(x, y)], [(x + 80, y)])
    v2 = view(b)
    check(abs(v2["yaw"] - v1["yaw"]) > 0.1, "a one-finger drag orbits the 3D scene")
    # a long press is the right button: dragged on, it pans (as a right drag) and never orbits
    touch(b, "touchStart", [(x, y)])
    b.wait_for("performance.now() > %f" % (b.evaluate("performance.now()") + 700))
    for k in range(1, 6):
        touch(b, "touchMove", [(x + 12 * k, y + 8 * k)])
        b.settle(1)
    touch(b, "touchEnd", [])
    b.settle(3)
    v3 = view(b)
    check(v3["yaw"] == v2["yaw"] and v3["pitch"] == v2["pitch"] and v3["target"] != v2["target"],
          "a long press and a drag pan the 3D scene as a right drag does, no orbit")

    phone(b, url)
    before = view(b)
    drag(b, [(x - 40, y), (x + 40, y)], [(x - 90, y), (x + 90, y)])
    pinched = view(b)
    check(pinched["scale2d"] > before["scale2d"] * 1.5,
          "a two-finger spread zooms the 2D scene in (x%.2f)" %
          (pinched["scale2d"] / before["scale2d"]))
    check(b.evaluate("visualViewport.scale") == 1, "the page itself keeps its scale 1")
    drag(b, [(x, y)], [(x + 60, y + 40)])
    after = view(b)
    moved = [after["centre2d"][i] != pinched["centre2d"][i] for i in (0, 1)]
    check(all(moved) and after["scale2d"] == pinched["scale2d"],
          "a one-finger drag pans the 2D scene")


# the phone's buttons (CSS pixels): the drawer's in the lower left corner, the 2D and 3D
# buttons at the drawer's top, the lecture's next slide at the bottom's middle
PHONE_BUTTONS = {"panels": (40, 812), 2: (90, 44), 3: (260, 44), "next": (212, 812)}


def test_taps(b, url, check):
    """The drawer opened by its button, then three taps on the 3D, 2D and 3D buttons, each
    acting on its own button (not where the last tap landed)."""
    phone(b, url)
    width = b.evaluate("Module.canvas.width") / 2
    tap(b, *PHONE_BUTTONS["panels"])
    check(view(b)["drawerOpen"], "a tap on Panels opens the drawer")
    got = []
    for which in (3, 2, 3):
        tap(b, *PHONE_BUTTONS[which])
        got.append(view(b)["dim"])
    check(got == [3, 2, 3], "three taps on 3D, 2D, 3D each act on their own button: %s" % got)
    tap(b, *PHONE_BUTTONS["panels"])
    x, y = scene_point(b)
    drag(b, [(x, y)], [(x + 40, y)])
    closed = view(b)
    check(closed["dim"] == 3 and not closed["drawerOpen"] and width == MOBILE[0],
          "the drawer closes again, the scene has the phone's whole width (%d CSS px)" % width)


def ink_rows(img, x_from):
    """The first and last rows with dark pixels (text, edges) right of `x_from`, over the
    lower buttons' band (the bottom 8%)."""
    rows = [y for y in range(int(img.height * 0.92))
            if any(min(img.pixel(x, y)) < 120 for x in range(x_from, img.width, 2))]
    return (rows[0], rows[-1]) if rows else (img.height, 0)


def test_phone_lecture(b, url, check):
    phone(b, url + "?lecture=paper")
    # held upright, the slide fills the screen (not a 16:9 band across its middle): its title
    # near the top, its caption near the bottom
    img = b.screenshot()
    top, bottom = ink_rows(img, int(img.width * 0.4))
    check(top < 0.12 * img.height and bottom > 0.75 * img.height,
          "on a phone held upright the slide fills the screen (text from %.0f%% to %.0f%% of its "
          "height)" % (100.0 * top / img.height, 100.0 * bottom / img.height))
    tap(b, *PHONE_BUTTONS["next"])
    after_button = view(b)["slide"]
    # a quick swipe to the left, high on the slide (no box there), 0.2 s from down to up
    t = time.time()
    touch(b, "touchStart", [(300, 200)], t)
    for k, x in enumerate((250, 180, 100)):
        touch(b, "touchMove", [(x, 205)], t + 0.05 * (k + 1))
    touch(b, "touchEnd", [], t + 0.2)
    b.settle(4)
    after_swipe = view(b)["slide"]
    check(after_button == 1 and after_swipe == 2,
          "on a phone the lecture's > button and a swipe to the left go on (slides %d, %d)" %
          (after_button, after_swipe))


# === Errors on the page

BAD_LINKS = ["?figure=99", "?slide=-1", "?lecture=paper&slide=-1", "?spray=abc", "?bogus",
             "?lecture=nosuch", "?lecture=own/nosuch.lecture"]


SHOWN = "(document.getElementById('problems') || {hidden: true}).hidden === false"


def problem_text(b):
    return b.evaluate("document.getElementById('problems').hidden ? '' : "
                      "document.getElementById('problem-list').textContent")


def test_bad_links(b, url, check):
    for link in BAD_LINKS:
        b.call("Page.navigate", url=url + link)
        try:
            b.wait_for(SHOWN, 5)
            b.wait_for("typeof Module === 'object' && Module.framesDrawn >= 3", 20)
            text = problem_text(b)
        except AssertionError:
            text = ""
        check(len(text) > 20, "%s: its message in the page, the viewer running: %r" % (link, text))
    # the browser's own line for the missing lecture's 404 is no error of the page's
    b.errors[:] = [e for e in b.errors if "nosuch" not in e]


NO_WEBGL2 = """HTMLCanvasElement.prototype.getContext = (function (get) {
  return function (kind, ...rest) {
    return /^webgl2$/.test(kind) ? null : get.call(this, kind, ...rest);
  };
})(HTMLCanvasElement.prototype.getContext);"""


def test_no_webgl2(b, url, check):
    added = b.call("Page.addScriptToEvaluateOnNewDocument", source=NO_WEBGL2)
    try:
        b.call("Page.navigate", url=url)
        b.wait_for(SHOWN, 5)
        text = problem_text(b)
    except AssertionError:
        text = ""
    finally:
        b.call("Page.removeScriptToEvaluateOnNewDocument", identifier=added["identifier"])
    check("WebGL 2" in text and "Try" in text,
          "without WebGL 2 the page says what the browser lacks and what to try: %r" % text[:80])


# === A lecture of one's own

OWN_LECTURE = """# a lecture of one's own: its shapes beside it and in a folder
slide A triangle of my own
shape shapes/triangle.txt
spray 200

slide An octahedron of my own
shape octahedron.off
"""
TRIANGLE = "# a triangle\n0 0\n4 0\n0 3\n"
OCTAHEDRON = ("OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n"
              "3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n")


def own_lecture_folder():
    """A folder as a lecturer would copy to a server: the lecture, its shapes beside it."""
    tmp = tempfile.mkdtemp(prefix="convexloc-lecture-")
    os.makedirs(os.path.join(tmp, "shapes"))
    for name, text in (("mine.lecture", OWN_LECTURE), ("shapes/triangle.txt", TRIANGLE),
                       ("octahedron.off", OCTAHEDRON)):
        with open(os.path.join(tmp, name), "w") as f:
            f.write(text)
    return tmp


def plays(b, check, how):
    b.wait_for("Module.view && Module.view.slides === 2", 10)
    first = view(b)
    b.key("PageDown", "PageDown", 34)
    b.settle(4)
    second = view(b)
    check(first["slide"] == 0 and first["dim"] == 2 and second["slide"] == 1 and second["dim"] == 3
          and problem_text(b) == "",
          "%s: the own lecture plays its slides with its shapes (%s -> %s)" %
          (how, (first["slide"], first["dim"]), (second["slide"], second["dim"])))


def test_own_lecture(b, url, check, folder):
    b.open(url + "?lecture=own/mine.lecture")
    plays(b, check, "?lecture=own/mine.lecture")
    b.open(url)
    doc = b.call("DOM.getDocument")
    node = b.call("DOM.querySelector", nodeId=doc["root"]["nodeId"], selector="#file")
    b.call("DOM.setFileInputFiles", nodeId=node["nodeId"], files=[
        os.path.join(folder, n) for n in ("mine.lecture", "shapes/triangle.txt", "octahedron.off")])
    plays(b, check, "the picker (three files at once)")


def test_early_file(b, url, check, folder):
    """A file chosen while the page still loads opens once the viewer has started."""
    b.call("Page.navigate", url=url)
    b.wait_for("document.getElementById('file') !== null", 10)
    early = not b.evaluate("typeof Module === 'object' && !!Module.calledRun")
    for attempt in range(5):  # the document may still be replaced while it loads
        try:
            doc = b.call("DOM.getDocument")
            node = b.call("DOM.querySelector", nodeId=doc["root"]["nodeId"], selector="#file")
            b.call("DOM.setFileInputFiles", nodeId=node["nodeId"],
                   files=[os.path.join(folder, "octahedron.off")])
            break
        except RuntimeError:
            time.sleep(0.1)
    b.wait_for("typeof Module === 'object' && Module.framesDrawn >= 3", 30)
    try:
        b.wait_for("Module.view && Module.view.dim === 3", 10)
        opened = True
    except AssertionError:
        opened = False
    check(opened, "a file chosen %s opens in the viewer" %
          ("while the page loads" if early else "(the page had already started)"))
