// convexloc's web page: the browser's wheel and touches, normalised once before the viewer
// sees them. A wheel's deltas in any unit become notches with GLFW's sign (up positive); a
// finger is the mouse (a tap is a click at its own spot, a long press a right-click, a drag
// pans or orbits), a finger dragged up or down over a panel scrolls it, two fingers pinch
// and pan the scene, and a quick swipe across the scene turns a lecture's slide.
'use strict';

(() => {
  const canvas = document.getElementById('canvas');
  // the browser's wheel units in one notch: pixels, lines, pages (deltaMode 0, 1, 2)
  const NOTCH = [100, 3, 1];
  const MOST_NOTCHES = 3;   // one wheel event moves at most this many notches
  const SLOP = 8;           // CSS pixels a finger may move and still tap
  const LONG_PRESS_MS = 500;
  const SWIPE_MS = 450;     // a swipe: quicker than this, longer than SWIPE_PX, mostly across
  const SWIPE_PX = 60;

  const ready = () => typeof Module === 'object' && Module.calledRun && !Module.stopped;

  // the canvas's pixels (the viewer's window pixels) per CSS pixel
  function pixelRatio() {
    const r = canvas.getBoundingClientRect();
    return r.width > 0 ? canvas.width / r.width : 1;
  }

  // a mouse event on the canvas at a CSS position: what Emscripten's GLFW reads the mouse from
  function mouse(type, p, button) {
    canvas.dispatchEvent(new MouseEvent(type, {
      clientX: p.x, clientY: p.y, button: button || 0, bubbles: true, cancelable: true}));
  }

  const notches = (delta, unit) =>
    Math.max(-MOST_NOTCHES, Math.min(MOST_NOTCHES, -delta / unit));

  // The wheel: the browser's deltas (down positive, in pixels, lines or pages) as notches,
  // up positive; Ctrl (a touchpad's pinch sends it) zooms the scene, never the page.
  function onWheel(e) {
    if (e.target !== canvas) return;
    e.preventDefault();
    e.stopPropagation();  // Emscripten's GLFW would pass the raw deltas on
    if (!ready()) return;
    const unit = NOTCH[e.deltaMode] || NOTCH[0];
    mouse('mousemove', {x: e.clientX, y: e.clientY});
    Module._convexloc_wheel(notches(e.deltaX, unit), notches(e.deltaY, unit), e.ctrlKey);
  }

  // === Touch: one gesture at a time, from the first finger down to the last one up
  // mode: none | pending (a finger down, not yet a tap or a drag) | drag (the left button
  // held) | right (a long press: the right button held) | scroll (a panel scrolled) |
  // pinch (two fingers) | over (a pinch's last finger, ignored until it lifts)
  // (frame: the frame count when the finger went down, or when a drag's press went)
  const touch = {mode: 'none', start: null, last: null, startMs: 0, frame: 0, timer: 0,
                 pair: null, overUi: false};

  const pointOf = (t) => ({x: t.clientX, y: t.clientY});

  function pairOf(list) {
    const a = pointOf(list[0]), b = pointOf(list[1]);
    return {x: (a.x + b.x) / 2, y: (a.y + b.y) / 2, d: Math.hypot(a.x - b.x, a.y - b.y)};
  }

  // whether the finger has moved from where it went down by more than a tap may
  const pastSlop = () =>
    Math.hypot(touch.last.x - touch.start.x, touch.last.y - touch.start.y) > SLOP;

  // the first finger: the pointer goes to it at once, the press waits for what it becomes
  function begin(p, ms) {
    Object.assign(touch, {mode: 'pending', start: p, last: p, startMs: ms,
                          frame: Module.framesDrawn});
    mouse('mousemove', p);
    touch.timer = setTimeout(() => {
      // a finger already past the slop is a drag waiting for a frame, however slow the page
      if (touch.mode !== 'pending' || pastSlop()) return;
      mouse('mousedown', touch.start, 2);
      touch.mode = 'right';
      touch.frame = Module.framesDrawn;
    }, LONG_PRESS_MS);
  }

  // `then` once the viewer has drawn a frame after frame `n`
  function afterFrame(n, then) {
    if (Module.framesDrawn > n) then();
    else requestAnimationFrame(() => afterFrame(n, then));
  }

  // The button a finger holds goes up where the finger is: the pointer moves there in a
  // frame after the press, the release in the next (a press, a move and a release in one
  // frame would read as a click where the finger lifted).
  function release() {
    clearTimeout(touch.timer);
    if (touch.mode !== 'drag' && touch.mode !== 'right') return;
    const p = touch.last, button = touch.mode === 'drag' ? 0 : 2;
    afterFrame(touch.frame, () => {
      mouse('mousemove', p);
      afterFrame(Module.framesDrawn, () => mouse('mouseup', p, button));
    });
  }

  function startPinch(list) {
    release();
    touch.mode = 'pinch';
    touch.pair = pairOf(list);
    mouse('mousemove', touch.pair);
  }

  // a finger past the slop: a scroll where it went up or down over a panel, else a drag
  // from where it went down (the viewer must have drawn a frame with the pointer there)
  function decide(p) {
    const dx = p.x - touch.start.x, dy = p.y - touch.start.y;
    if (Math.hypot(dx, dy) <= SLOP || Module.framesDrawn === touch.frame) return;
    clearTimeout(touch.timer);
    touch.overUi = !!Module.pointerOverUi;
    if (touch.overUi && Math.abs(dy) > Math.abs(dx)) {
      touch.mode = 'scroll';
      Module._convexloc_scroll_pixels(dy * pixelRatio());
      return;
    }
    // the press where the finger went down; the pointer follows from the next frame on
    touch.mode = 'drag';
    touch.frame = Module.framesDrawn;
    mouse('mousedown', touch.start, 0);
  }

  function pinch(q) {
    const was = touch.pair, r = pixelRatio();
    mouse('mousemove', q);
    Module._convexloc_pinch(was.d > 0 && q.d > 0 ? q.d / was.d : 1, (q.x - was.x) * r,
                            (q.y - was.y) * r);
    touch.pair = q;
  }

  // touch.last: where the finger is now
  function move(p) {
    const was = touch.last;
    touch.last = p;
    if (touch.mode === 'pending') return decide(p);
    if (touch.mode === 'scroll')
      return Module._convexloc_scroll_pixels((p.y - was.y) * pixelRatio());
    if (touch.mode === 'drag' && Module.framesDrawn === touch.frame) return;
    if (touch.mode === 'drag' || touch.mode === 'right') mouse('mousemove', p);
  }

  // a quick drag across the scene in a lecture: the next slide (to the left) or the previous
  // (`ms`: when the finger lifted, as the event's time stamp; a busy page handles it later)
  function swipe(p, ms) {
    const dx = p.x - touch.start.x, dy = p.y - touch.start.y;
    const lecture = Module.view && Module.view.slides > 1;
    if (lecture && !touch.overUi && ms - touch.startMs < SWIPE_MS &&
        Math.abs(dx) > SWIPE_PX && Math.abs(dx) > 2 * Math.abs(dy))
      Module._convexloc_lecture_step(dx < 0 ? 1 : -1);
  }

  // The last finger up: a finger that never went past the slop is a click at its spot; one
  // that went past it before the viewer drew a frame, a flick (a swipe, never a click).
  function end(ms) {
    clearTimeout(touch.timer);
    const flick = pastSlop();
    if (touch.mode === 'pending' && flick) {
      touch.overUi = !!Module.pointerOverUi;
      swipe(touch.last, ms);
    } else if (touch.mode === 'pending') {
      mouse('mousedown', touch.start, 0);
      mouse('mouseup', touch.start, 0);
    } else {
      if (touch.mode === 'drag') swipe(touch.last, ms);
      release();
    }
    touch.mode = 'none';
  }

  function onTouch(e) {
    if (e.target !== canvas) return;
    e.preventDefault();   // no page zoom or scroll, no mouse events made up by the browser
    e.stopPropagation();  // Emscripten's GLFW would press at the last mouse position
    if (!ready()) return;
    const n = e.touches.length;
    if (e.type === 'touchstart') {
      if (n === 1 && touch.mode === 'none') begin(pointOf(e.touches[0]), e.timeStamp);
      else if (n >= 2 && touch.mode !== 'pinch' && touch.mode !== 'over') startPinch(e.touches);
    } else if (e.type === 'touchmove') {
      if (touch.mode === 'pinch' && n >= 2) pinch(pairOf(e.touches));
      else if (n >= 1 && touch.mode !== 'over') move(pointOf(e.touches[0]));
    } else if (e.type === 'touchcancel') {
      release();
      touch.mode = 'none';
    } else if (touch.mode === 'pinch' || touch.mode === 'over') {
      touch.mode = n === 0 ? 'none' : 'over';
    } else if (n === 0) {
      end(e.timeStamp);
    }
  }

  const active = {capture: true, passive: false};
  window.addEventListener('wheel', onWheel, active);
  for (const kind of ['touchstart', 'touchmove', 'touchend', 'touchcancel'])
    window.addEventListener(kind, onTouch, active);
})();
