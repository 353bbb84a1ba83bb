// convexloc-viewer — the one place that includes the OpenGL loader: glad's for OpenGL 3.3
// core, or GL ES 3's header for WebGL 2 (the web page, CONVEXLOC_GLES), which needs none.
#pragma once

#if CONVEXLOC_GLES
#include <GLES3/gl3.h>
#else
#include <glad/gl.h>
#endif
