# Writes a C++ source defining `const char NAME[]` as the text of INPUT, for
# text a binary carries (report.html's 3D view script, CMakeLists.txt).
#   cmake -DINPUT=in.js -DOUTPUT=out.cc -DNAME=kText -DHEADER=pfdm/x/y.h
#         -P embed_text.cmake
file(READ "${INPUT}" text)
foreach(forbidden ")pfdm_text\"" "</script")
  string(FIND "${text}" "${forbidden}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${INPUT} holds '${forbidden}', which cannot be embedded")
  endif()
endforeach()
# A raw string literal in pieces of 60,000 characters: compilers need not
# take longer string literals, and adjacent ones join.
string(LENGTH "${text}" length)
set(pieces "")
set(begin 0)
while(begin LESS length)
  string(SUBSTRING "${text}" ${begin} 60000 piece)
  string(APPEND pieces "R\"pfdm_text(${piece})pfdm_text\"\n")
  math(EXPR begin "${begin} + 60000")
endwhile()
file(WRITE "${OUTPUT}.tmp"
  "// Generated from ${INPUT} by cmake/embed_text.cmake: do not edit.\n"
  "#include \"${HEADER}\"\n\nnamespace pfdm {\n\nconst char ${NAME}[] =\n"
  "${pieces};\n\n}  // namespace pfdm\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
