# cmake -DINPUT=<text file> -DOUTPUT=<.cpp> -DFUNCTION=<name> -P embed_text.cmake
# Writes a .cpp whose function `std::string_view ps::FUNCTION()` returns INPUT verbatim as a
# raw string literal. Run as a custom command that DEPENDS on INPUT, so edits rebuild.
file(READ "${INPUT}" _text)
set(_delim "ps_embed")
string(FIND "${_text}" ")${_delim}\"" _clash)
if(NOT _clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )${_delim}\"")
endif()
set(_out "// Generated from ${INPUT} by src/scene/embed_text.cmake; do not edit.\n")
string(APPEND _out "#include <string_view>\n\nnamespace ps {\n\n")
string(APPEND _out "std::string_view ${FUNCTION}() {\n  return R\"${_delim}(${_text})${_delim}\";\n}\n\n")
string(APPEND _out "}  // namespace ps\n")
file(WRITE "${OUTPUT}.tmp" "${_out}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
