# The service library's sources, stated once for the main build (service/CMakeLists.txt) and the
# fuzz build (fuzz/CMakeLists.txt, whose HTTP engine harness runs the real service):
#   cutcalc_service_sources(<root> <binary dir> <out var>)
# sets <out var> to the hand-written sources and the three generated at build time (openapi.yaml
# and the web page embedded, build facts for GET /version).
function(cutcalc_service_sources root binary_dir out_var)
  set(sources config.cpp cors.cpp cpu_budget.cpp http_app.cpp socket_addresses.cpp http_event_loop.cpp
              http_framing.cpp http_request.cpp http_response.cpp http_tuning.cpp
              listener.cpp logging.cpp metrics.cpp request_id.cpp signals.cpp web_assets.cpp
              work_pool.cpp)
  list(TRANSFORM sources PREPEND ${root}/service/)

  # The contract served at GET /openapi.yaml.
  set(openapi_embedded ${binary_dir}/openapi_embedded.cpp)
  add_custom_command(
    OUTPUT ${openapi_embedded}
    COMMAND ${CMAKE_COMMAND} -DINPUT=${root}/openapi.yaml -DOUTPUT=${openapi_embedded}
            -DSYMBOL=embedded_openapi_yaml -P ${root}/cmake/EmbedFile.cmake
    DEPENDS ${root}/openapi.yaml ${root}/cmake/EmbedFile.cmake
    COMMENT "Embedding openapi.yaml")

  # The calculator page served at GET / and its assets under /ui/ (web/). The glob re-runs on
  # every build (CONFIGURE_DEPENDS), so an added, removed or edited web file regenerates the table.
  file(GLOB_RECURSE web_files CONFIGURE_DEPENDS ${root}/web/*)
  set(web_embedded ${binary_dir}/web_assets_embedded.cpp)
  add_custom_command(
    OUTPUT ${web_embedded}
    COMMAND ${CMAKE_COMMAND} -DWEB_DIR=${root}/web -DOUTPUT=${web_embedded}
            -P ${root}/cmake/EmbedWebAssets.cmake
    DEPENDS ${web_files} ${root}/cmake/EmbedWebAssets.cmake
    COMMENT "Embedding the web page (web/)")

  # Build facts for GET /version (-DCUTCALC_GIT_COMMIT=... where there is no .git, e.g. in a
  # container).
  set(commit ${CUTCALC_GIT_COMMIT})
  if(NOT commit)
    execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${root}
                    OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE
                    ERROR_QUIET RESULT_VARIABLE git_result)
    if(NOT git_result EQUAL 0 OR commit STREQUAL "")
      set(commit "unknown")
    endif()
  endif()
  set(CUTCALC_GIT_COMMIT ${commit})
  configure_file(${root}/service/build_info.cpp.in ${binary_dir}/build_info.cpp @ONLY)

  set(${out_var} ${sources} ${openapi_embedded} ${web_embedded} ${binary_dir}/build_info.cpp
      PARENT_SCOPE)
endfunction()
