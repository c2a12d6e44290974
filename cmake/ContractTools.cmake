# The contract checker of the tests is Node.js code (tools/contract: Ajv, JSON Schema 2020-12).
# Configuring installs its locked packages once (npm ci, again only when package-lock.json is newer
# than the installed tree), so ctest finds them on a clean clone.
find_program(CUTCALC_NODE node REQUIRED DOC "Node.js, for the contract checker (tools/contract)")
find_program(CUTCALC_NPM npm REQUIRED DOC "npm, to install tools/contract's locked packages")
get_filename_component(CUTCALC_CONTRACT_TOOLS "${CMAKE_CURRENT_LIST_DIR}/../tools/contract" ABSOLUTE)
set(_installed "${CUTCALC_CONTRACT_TOOLS}/node_modules/.package-lock.json")
if(NOT EXISTS "${_installed}" OR "${CUTCALC_CONTRACT_TOOLS}/package-lock.json" IS_NEWER_THAN
                                  "${_installed}")
  message(STATUS "tools/contract: npm ci")
  execute_process(
    COMMAND ${CUTCALC_NPM} ci --no-audit --no-fund --loglevel=error
    WORKING_DIRECTORY "${CUTCALC_CONTRACT_TOOLS}"
    RESULT_VARIABLE _npm_result)
  if(NOT _npm_result EQUAL 0)
    message(FATAL_ERROR "npm ci in ${CUTCALC_CONTRACT_TOOLS} failed (${_npm_result})")
  endif()
endif()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
                                       "${CUTCALC_CONTRACT_TOOLS}/package-lock.json")
