# The contract checker of the tests is Node.js code (tools/contract: Ajv, JSON Schema 2020-12). Its
# locked packages are installed by scripts/setup.sh (npm ci), never by the build: configuring only
# checks that they are there.
find_program(CUTCALC_NODE node REQUIRED DOC "Node.js, for the contract checker (tools/contract)")
get_filename_component(CUTCALC_CONTRACT_TOOLS "${CMAKE_CURRENT_LIST_DIR}/../tools/contract" ABSOLUTE)
set(_installed "${CUTCALC_CONTRACT_TOOLS}/node_modules/.package-lock.json")
if(NOT EXISTS "${_installed}" OR "${CUTCALC_CONTRACT_TOOLS}/package-lock.json" IS_NEWER_THAN
                                  "${_installed}")
  message(FATAL_ERROR "tools/contract's packages are missing or older than package-lock.json: "
                      "run scripts/setup.sh (it runs npm ci there)")
endif()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
                                       "${CUTCALC_CONTRACT_TOOLS}/package-lock.json")
