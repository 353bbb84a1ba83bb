# The web page's dependencies under Emscripten (scripts/web.sh configures this build), with
# the names the native build's targets have, so that the rest of CMakeLists.txt is shared:
#   PkgConfig::IMGUI  Dear ImGui 1.86 compiled from Debian's imgui source package (fetched
#                     by scripts/web.sh into CONVEXLOC_IMGUI_SOURCE_DIR), its GLFW and
#                     OpenGL 3 backends on GL ES 3 (WebGL 2)
#   glfw, OpenGL::GL  Emscripten's own GLFW 3 and WebGL 2: link options, nothing built
#   convexloc_glad    empty: WebGL's functions need no loader
#   glm::glm, CLI11::CLI11, stb: the host's header-only Debian packages, each folder alone
#                     (/usr/include as a whole would shadow the C headers of the sysroot)

set(CONVEXLOC_IMGUI_SOURCE_DIR "" CACHE PATH
    "Dear ImGui 1.86's sources, Debian's imgui source package (scripts/web.sh fetches them)")
if(NOT EXISTS "${CONVEXLOC_IMGUI_SOURCE_DIR}/imgui.cpp")
  message(FATAL_ERROR "the web build needs Dear ImGui's sources: CONVEXLOC_IMGUI_SOURCE_DIR "
                      "('${CONVEXLOC_IMGUI_SOURCE_DIR}') has no imgui.cpp; scripts/web.sh "
                      "fetches them with apt-get source imgui")
endif()

# the host's header-only packages, one folder each
set(CONVEXLOC_HOST_HEADERS ${CMAKE_CURRENT_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${CONVEXLOC_HOST_HEADERS})
foreach(dir glm CLI stb)
  if(NOT IS_DIRECTORY /usr/include/${dir})
    message(FATAL_ERROR "the web build needs /usr/include/${dir} (Debian's libglm-dev, "
                        "libcli11-dev, libstb-dev)")
  endif()
  file(CREATE_LINK /usr/include/${dir} ${CONVEXLOC_HOST_HEADERS}/${dir} SYMBOLIC)
endforeach()
add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE ${CONVEXLOC_HOST_HEADERS})
add_library(CLI11::CLI11 INTERFACE IMPORTED)
target_include_directories(CLI11::CLI11 SYSTEM INTERFACE ${CONVEXLOC_HOST_HEADERS})

# WebGL 2 only (GLSL ES 3.00), and Emscripten's GLFW 3
add_library(OpenGL::GL INTERFACE IMPORTED)
target_link_options(OpenGL::GL INTERFACE -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2)
add_library(glfw INTERFACE IMPORTED)
target_link_options(glfw INTERFACE -sUSE_GLFW=3)
add_library(convexloc_glad INTERFACE)
target_compile_definitions(convexloc_glad INTERFACE CONVEXLOC_GLES=1)

# Dear ImGui: third-party code, compiled without our warning flags
set(imgui ${CONVEXLOC_IMGUI_SOURCE_DIR})
add_library(convexloc_imgui STATIC
  ${imgui}/imgui.cpp ${imgui}/imgui_draw.cpp ${imgui}/imgui_tables.cpp
  ${imgui}/imgui_widgets.cpp ${imgui}/imgui_demo.cpp
  ${imgui}/backends/imgui_impl_glfw.cpp ${imgui}/backends/imgui_impl_opengl3.cpp)
target_include_directories(convexloc_imgui SYSTEM PUBLIC ${imgui}
                           ${CONVEXLOC_HOST_HEADERS}/stb)
target_compile_definitions(convexloc_imgui PRIVATE IMGUI_IMPL_OPENGL_ES3)
target_link_libraries(convexloc_imgui PUBLIC glfw)
add_library(PkgConfig::IMGUI ALIAS convexloc_imgui)

# the page's packed files: the shaders (turned into GLSL ES 3.00, see page.cmake), the shapes
set(CONVEXLOC_VIEWER_SHADER_DIR /shaders)
set(CONVEXLOC_VIEWER_ASSET_DIR /assets)
