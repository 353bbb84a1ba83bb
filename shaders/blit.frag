// convexloc-viewer: the cached scene, pixel for pixel.
#version 330 core
in vec2 vUv;
uniform sampler2D uScene;
out vec4 fragColour;

void main() {
  fragColour = texture(uScene, vUv);
}
