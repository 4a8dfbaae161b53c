# cablefit_library(NAME <target> ALIAS <ns::name> DIR <dir> SOURCES <src/x.cc ...>
#                  [DEPS ...] [PRIVATE_DEPS ...])
# One library per folder: public headers live in DIR/include, sources and private headers in
# DIR/src. SOURCES are listed (relative to DIR) so the CMake file says what is built.
function(cablefit_library)
  cmake_parse_arguments(L "" "NAME;ALIAS;DIR" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  if(NOT L_SOURCES)
    message(FATAL_ERROR "cablefit_library(${L_NAME}): no SOURCES")
  endif()
  list(TRANSFORM L_SOURCES PREPEND ${L_DIR}/)
  add_library(${L_NAME} STATIC ${L_SOURCES})
  add_library(${L_ALIAS} ALIAS ${L_NAME})
  # Position-independent so the FreeCAD workbench's Python module can link the same libraries.
  set_target_properties(${L_NAME} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${L_NAME} PUBLIC ${L_DIR}/include PRIVATE ${L_DIR}/src)
  target_link_libraries(${L_NAME} PUBLIC ${L_DEPS} PRIVATE ${L_PRIVATE_DEPS} cablefit_warnings)
endfunction()

# cablefit_test(NAME <exe> SOURCES <x_test.cc ...> LIBS ...): one GoogleTest executable of the
# listed sources (relative to the calling folder), registered with CTest test by test.
function(cablefit_test)
  cmake_parse_arguments(T "" "NAME" "SOURCES;LIBS" ${ARGN})
  if(NOT T_SOURCES)
    message(FATAL_ERROR "cablefit_test(${T_NAME}): no SOURCES")
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} cablefit_test_support GTest::gtest_main cablefit_warnings)
  # One variable per property: gtest_discover_tests splits a ';'-list value into separate
  # arguments, which silently dropped the second variable of a single ENVIRONMENT list.
  gtest_discover_tests(${T_NAME} DISCOVERY_TIMEOUT 60 PROPERTIES
    ENVIRONMENT "CABLEFIT_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
    ENVIRONMENT_MODIFICATION "CABLEFIT_BINARY_DIR=set:${PROJECT_BINARY_DIR}")
endfunction()
