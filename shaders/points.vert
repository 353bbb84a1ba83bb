// convexloc-viewer: sprayed points, one vertex each; the class picks the colour and whether
// the point is drawn at all, so filters and themes never re-upload the points.
#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in uint aClass;  // 0 inside, 1 boundary, 2 outside

uniform mat4 uClipFromLocal;
uniform float uPointSize;      // window pixels
uniform float uPixelRatio;
uniform float uBoundaryScale;  // boundary points are drawn larger
uniform vec4 uColours[3];
uniform int uVisible;          // bit c set: class c is drawn

flat out vec4 vColour;
flat out float vSize;
flat out int vRim;

void main() {
  int c = int(aClass);
  if (((uVisible >> c) & 1) == 0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume
    gl_PointSize = 1.0;
    vColour = vec4(0.0);
    vSize = 0.0;
    vRim = 0;
    return;
  }
  gl_Position = uClipFromLocal * vec4(aPos, 1.0);
  float s = uPointSize * uPixelRatio * (c == 1 ? uBoundaryScale : 1.0);
  gl_PointSize = max(s, 1.0);
  vSize = s;
  vColour = uColours[c];
  vRim = c == 1 ? 1 : 0;
}
