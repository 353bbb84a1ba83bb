// convexloc-viewer: screen-sized markers (centre, handles, placed points).
#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec4 aColour;
layout(location = 2) in vec2 aSizeShape;  // diameter in window pixels, shape

uniform mat4 uClipFromLocal;
uniform float uPixelRatio;

out vec4 vColour;
flat out float vSize;
flat out int vShape;

void main() {
  gl_Position = uClipFromLocal * vec4(aPos, 1.0);
  float size = aSizeShape.x * uPixelRatio + 2.0;  // room for the feather
  gl_PointSize = size;
  vSize = size;
  vShape = int(aSizeShape.y + 0.5);
  vColour = aColour;
}
