# cmake -DWEB_DIR=dir -DOUTPUT=file.cpp -P EmbedWebAssets.cmake
# Writes one C++ source with the table of service/web_assets.h: every file under WEB_DIR (names
# starting with a dot are skipped) with its URL path, content type and bytes. web/index.html is
# served at "/", web/<path> at "/<path>". A file whose extension has no known content type stops
# the build, so nothing is ever served with a guessed type.
cmake_minimum_required(VERSION 3.20)  # script mode: today's policies (IN_LIST, ...)
if(NOT WEB_DIR OR NOT OUTPUT)
  message(FATAL_ERROR "EmbedWebAssets.cmake needs -DWEB_DIR=... and -DOUTPUT=...")
endif()

file(GLOB_RECURSE files RELATIVE "${WEB_DIR}" "${WEB_DIR}/*")
list(FILTER files EXCLUDE REGEX "(^|/)\\.")
list(SORT files)
if(NOT "index.html" IN_LIST files)
  message(FATAL_ERROR "${WEB_DIR}/index.html is missing")
endif()

set(arrays "")
set(rows "")
set(index 0)
foreach(file IN LISTS files)
  if(NOT file MATCHES "^[A-Za-z0-9._/-]+$")
    message(FATAL_ERROR "web asset name '${file}': use only letters, digits, '.', '_', '-', '/'")
  endif()
  string(REGEX MATCH "\\.[A-Za-z0-9]+$" extension "${file}")
  string(TOLOWER "${extension}" extension)
  if(extension STREQUAL ".html")
    set(type "text/html; charset=utf-8")
  elseif(extension STREQUAL ".css")
    set(type "text/css; charset=utf-8")
  elseif(extension STREQUAL ".js" OR extension STREQUAL ".mjs")
    set(type "text/javascript; charset=utf-8")
  elseif(extension STREQUAL ".svg")
    set(type "image/svg+xml")
  elseif(extension STREQUAL ".png")
    set(type "image/png")
  elseif(extension STREQUAL ".ico")
    set(type "image/x-icon")
  else()
    message(FATAL_ERROR "web asset '${file}': no content type known for '${extension}'")
  endif()
  if(file STREQUAL "index.html")
    set(url "/")
  else()
    set(url "/${file}")
  endif()

  file(READ "${WEB_DIR}/${file}" hex HEX)
  string(LENGTH "${hex}" hex_length)
  math(EXPR byte_count "${hex_length} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${hex}")
  string(REGEX REPLACE "(('\\\\x[0-9a-f][0-9a-f]',){16})" "\\1\n" bytes "${bytes}")
  string(APPEND arrays "// ${file}\nconstexpr char kFile${index}[] = {\n${bytes}'\\0'};\n")
  string(APPEND rows "    {\"${url}\", \"${file}\", \"${type}\", {kFile${index}, ${byte_count}}},\n")
  math(EXPR index "${index} + 1")
endforeach()

file(WRITE "${OUTPUT}.tmp"
"// Generated from ${WEB_DIR} by cmake/EmbedWebAssets.cmake; do not edit.\n"
"#include <array>\n"
"#include \"service/web_assets.h\"\n"
"namespace cutcalc::service {\n"
"namespace {\n${arrays}"
"constexpr std::array<WebAsset, ${index}> kAssets = {{\n${rows}}};\n"
"}  // namespace\n"
"std::span<const WebAsset> web_assets() { return kAssets; }\n"
"}  // namespace cutcalc::service\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
