// convexloc-viewer: marker shapes: 0 disc, 1 ring, 2 cross in a ring, 3 square.
#version 330 core
in vec4 vColour;
flat in float vSize;
flat in int vShape;
out vec4 fragColour;

void main() {
  vec2 p = (gl_PointCoord - vec2(0.5)) * vSize;  // pixels from the middle
  float r = length(p);
  float radius = 0.5 * vSize - 1.0;
  float coverage;
  if (vShape == 0) {
    coverage = clamp(radius - r + 0.5, 0.0, 1.0);
  } else if (vShape == 1) {
    coverage = clamp(1.5 - abs(r - (radius - 1.0)), 0.0, 1.0);
  } else if (vShape == 2) {
    float ring = clamp(1.25 - abs(r - (radius - 1.0)), 0.0, 1.0);
    float bar = clamp(1.25 - min(abs(p.x), abs(p.y)), 0.0, 1.0) * clamp(radius - 2.5 - r + 0.5, 0.0, 1.0);
    coverage = max(ring, bar);
  } else {
    coverage = clamp(radius - max(abs(p.x), abs(p.y)) + 0.5, 0.0, 1.0);
  }
  if (coverage <= 0.0) discard;
  fragColour = vec4(vColour.rgb, vColour.a * coverage);
}
