// convexloc-viewer: line segments of constant pixel width, one instance per segment,
// expanded to a screen-space quad with square caps and a one-pixel feather.
#version 330 core
layout(location = 0) in vec3 aStart;
layout(location = 1) in vec3 aEnd;
layout(location = 2) in vec4 aColour;
layout(location = 3) in vec2 aStyle;  // width in pixels, dash length in pixels (0: solid)

uniform mat4 uClipFromLocal;
uniform vec2 uViewport;     // framebuffer size in pixels
uniform float uPixelRatio;  // framebuffer pixels per window pixel

out vec4 vColour;
noperspective out float vAcross;  // pixels from the centre line
noperspective out float vAlong;   // pixels from the start
flat out float vHalfWidth;
flat out float vDash;

// pulls an end that lies behind the eye onto a plane just in front of it (3D)
vec4 inFront(vec4 c, vec4 other) {
  const float nearW = 1e-6;
  if (c.w >= nearW) return c;
  float t = (nearW - c.w) / (other.w - c.w);
  return mix(c, other, clamp(t, 0.0, 1.0));
}

void main() {
  vec4 c0 = uClipFromLocal * vec4(aStart, 1.0);
  vec4 c1 = uClipFromLocal * vec4(aEnd, 1.0);
  vec4 k0 = inFront(c0, c1);
  vec4 k1 = inFront(c1, c0);
  vec2 s0 = (k0.xy / k0.w * 0.5 + 0.5) * uViewport;
  vec2 s1 = (k1.xy / k1.w * 0.5 + 0.5) * uViewport;
  vec2 d = s1 - s0;
  float len = length(d);
  vec2 dir = len > 1e-4 ? d / len : vec2(1.0, 0.0);
  vec2 nrm = vec2(-dir.y, dir.x);

  float halfWidth = 0.5 * aStyle.x * uPixelRatio;
  float reach = halfWidth + 1.0;
  int corner = gl_VertexID;  // 0..3, a triangle strip
  float side = (corner == 0 || corner == 2) ? -1.0 : 1.0;
  bool atEnd = corner >= 2;
  vec4 c = atEnd ? k1 : k0;
  vec2 s = (atEnd ? s1 : s0) + nrm * side * reach + dir * (atEnd ? reach : -reach);

  gl_Position = vec4((s / uViewport * 2.0 - 1.0) * c.w, c.z, c.w);
  vColour = aColour;
  vAcross = side * reach;
  vAlong = atEnd ? len + reach : -reach;
  vHalfWidth = halfWidth;
  // a segment reaching far off screen (deep zoom) is drawn solid: its dash phase would need
  // more precision than a float has at that length
  vDash = len > 16384.0 ? 0.0 : aStyle.y * uPixelRatio;
}
