// convexloc-viewer: flat colour, or a soft headlight for faces that carry a normal.
#version 330 core
in vec4 vColour;
in vec3 vNormal;
in vec3 vToEye;
out vec4 fragColour;

void main() {
  vec4 c = vColour;
  if (dot(vNormal, vNormal) > 0.0) {
    float facing = abs(dot(normalize(vNormal), normalize(vToEye)));
    c.rgb *= 0.45 + 0.55 * facing;
  }
  fragColour = c;
}
