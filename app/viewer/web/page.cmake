# The web page (scripts/web.sh): convexloc-viewer linked for the browser into site/, beside
# index.html and page.js, with its files packed into convexloc-viewer.data:
#   /shaders  the shaders in GLSL ES 3.00, made from the same files at configure time: ES's
#             #version line and precisions come first (WebGL takes no comment before them),
#             and `noperspective` goes (ES has none; the thick segments' coverage is then
#             interpolated with perspective)
#   /assets   the shipped shapes and lectures
#   the DejaVu Sans font at its Debian path, where ui/style.cpp looks for it

set(CONVEXLOC_SITE_DIR ${CMAKE_BINARY_DIR}/site)
set(es_shaders ${CMAKE_CURRENT_BINARY_DIR}/shaders-es)
file(MAKE_DIRECTORY ${es_shaders})
file(GLOB shader_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/shaders/*.vert
     ${PROJECT_SOURCE_DIR}/shaders/*.frag)
foreach(source IN LISTS shader_sources)
  file(READ ${source} text)
  string(FIND "${text}" "#version 330 core\n" at)
  if(at LESS 0)
    message(FATAL_ERROR "${source}: no '#version 330 core' line to turn into GLSL ES 3.00")
  endif()
  # WebGL wants the #version line first, before any comment
  string(REPLACE "#version 330 core\n" "" text "${text}")
  string(PREPEND text "#version 300 es\nprecision highp float;\nprecision highp int;\n")
  string(REPLACE "noperspective " "" text "${text}")
  get_filename_component(name ${source} NAME)
  file(WRITE ${es_shaders}/${name}.new "${text}")
  file(COPY_FILE ${es_shaders}/${name}.new ${es_shaders}/${name} ONLY_IF_DIFFERENT)
  file(REMOVE ${es_shaders}/${name}.new)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${source})
endforeach()

set(packed "${es_shaders}@/shaders" "${PROJECT_SOURCE_DIR}/assets@/assets")
set(font /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf)
if(EXISTS ${font})
  list(APPEND packed "${font}@${font}")
else()
  message(WARNING "${font} is missing (Debian's fonts-dejavu-core): the page uses ImGui's font")
endif()
file(GLOB_RECURSE packed_files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/assets/*)
list(TRANSFORM shader_sources REPLACE "^.*/" "${es_shaders}/" OUTPUT_VARIABLE es_files)

set_target_properties(convexloc-viewer PROPERTIES
  RUNTIME_OUTPUT_DIRECTORY ${CONVEXLOC_SITE_DIR}
  LINK_DEPENDS "${es_files};${packed_files};${CMAKE_CURRENT_SOURCE_DIR}/web/page.cmake")
foreach(p IN LISTS packed)
  target_link_options(convexloc-viewer PRIVATE "SHELL:--preload-file ${p}")
endforeach()
target_link_options(convexloc-viewer PRIVATE
  -sENVIRONMENT=web
  -sALLOW_MEMORY_GROWTH=1
  -sEXPORTED_FUNCTIONS=_main,_convexloc_open_file,_convexloc_wheel,_convexloc_pinch,_convexloc_scroll_pixels,_convexloc_lecture_step
  -sEXPORTED_RUNTIME_METHODS=FS,ccall)

# the page around the canvas
foreach(file index.html page.js files.js input.js)
  configure_file(${CMAKE_CURRENT_SOURCE_DIR}/web/${file} ${CONVEXLOC_SITE_DIR}/${file} COPYONLY)
endforeach()
