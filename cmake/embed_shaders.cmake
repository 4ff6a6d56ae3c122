# Turns GLSL files into C++ string constants:
# cmake -DOUT=<header> -DROOT=<source dir> -DSOURCES=<a|b|...> -P embed_shaders.cmake
string(REPLACE "|" ";" SOURCES "${SOURCES}")
set(text "// Generated from shaders/*.glsl by cmake/embed_shaders.cmake; do not edit.\n#pragma once\n\nnamespace gps::shaders {\n")
foreach(source ${SOURCES})
  get_filename_component(name ${source} NAME_WE)
  file(READ ${source} body)
  # A C++ header shared with GLSL (core/patches/patch_basis.h) is read as GLSL under GPS_GLSL.
  if(source MATCHES "\\.h$")
    set(body "#define GPS_GLSL\n${body}")
  else()
    # A shader's #include "x.h" or "x.glsl" (GLSL has none) takes that file's text in its place: a
    # shared C++ header is read as GLSL (GPS_GLSL is defined by core/patches/patch_basis.h, which comes
    # before such a shader); a .glsl file is a piece two shaders share (not itself embedded).
    # A .glsl piece may include pieces itself: replaced until none is left (a C++ header's own
    # includes stay, in its C++ part).
    string(REGEX MATCHALL "#include \"[^\"]+\\.(h|glsl)\"" includes "${body}")
    while(includes)
      foreach(line ${includes})
        string(REGEX REPLACE "#include \"([^\"]+)\"" "\\1" header "${line}")
        file(READ ${ROOT}/${header} header_body)
        string(REPLACE "${line}" "${header_body}" body "${body}")
      endforeach()
      string(REGEX MATCHALL "#include \"[^\"]+\\.glsl\"" includes "${body}")
    endwhile()
  endif()
  string(APPEND text "inline constexpr const char* ${name} = R\"glsl(${body})glsl\";\n")
endforeach()
string(APPEND text "}  // namespace gps::shaders\n")
file(WRITE ${OUT}.tmp "${text}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
