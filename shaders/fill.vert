// convexloc-viewer: filled triangles: 2D cells and polygons (unlit), 3D faces (lit).
#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec4 aColour;
layout(location = 2) in vec3 aNormal;  // zero: unlit

uniform mat4 uClipFromLocal;
uniform vec3 uEye;  // the eye in local coordinates (3D lighting)

out vec4 vColour;
out vec3 vNormal;
out vec3 vToEye;

void main() {
  gl_Position = uClipFromLocal * vec4(aPos, 1.0);
  vColour = aColour;
  vNormal = aNormal;
  vToEye = uEye - aPos;
}
