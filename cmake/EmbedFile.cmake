# cmake -DINPUT=file -DOUTPUT=file.cpp -DSYMBOL=name -P EmbedFile.cmake
# Writes a C++ source defining `std::string_view SYMBOL()` with the file's bytes, so the binary
# serves exactly the file that was in the tree when it was built.
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" hex_length)
math(EXPR byte_count "${hex_length} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
string(REGEX REPLACE "(('\\\\x[0-9a-f][0-9a-f]',){16})" "\\1\n" bytes "${bytes}")
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${INPUT} by cmake/EmbedFile.cmake; do not edit.\n"
"#include <string_view>\n"
"namespace cutcalc::service {\n"
"namespace { constexpr char kBytes[] = {\n${bytes}'\\0'}; }\n"
"std::string_view ${SYMBOL}() { return {kBytes, ${byte_count}}; }\n"
"}  // namespace cutcalc::service\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
