// convexloc-viewer: anti-aliased, optionally dashed segments.
#version 330 core
in vec4 vColour;
noperspective in float vAcross;
noperspective in float vAlong;
flat in float vHalfWidth;
flat in float vDash;
out vec4 fragColour;

void main() {
  if (vDash > 0.0 && mod(vAlong, 2.0 * vDash) > vDash) discard;
  float coverage = clamp(vHalfWidth + 0.5 - abs(vAcross), 0.0, 1.0);
  if (coverage <= 0.0) discard;
  fragColour = vec4(vColour.rgb, vColour.a * coverage);
}
