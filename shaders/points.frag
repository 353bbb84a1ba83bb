// convexloc-viewer: round points with a soft edge; tiny ones are plain squares (cheap for
// a million of them); boundary points get a dark rim.
#version 330 core
flat in vec4 vColour;
flat in float vSize;
flat in int vRim;
uniform vec4 uRim;
out vec4 fragColour;

void main() {
  if (vSize < 2.5) {
    fragColour = vColour;
    return;
  }
  float radius = 0.5 * vSize;
  float r = length(gl_PointCoord - vec2(0.5)) * vSize;
  float coverage = clamp(radius - r + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  vec4 colour = vColour;
  if (vRim == 1) colour = mix(colour, uRim, clamp(r - (radius - 1.6), 0.0, 1.0));
  fragColour = vec4(colour.rgb, colour.a * coverage);
}
