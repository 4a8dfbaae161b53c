# cablefit_library(NAME <target> ALIAS <ns::name> DIR <dir> [DEPS ...] [PRIVATE_DEPS ...])
# One library per folder: sources are every src/*.cc, public headers live in include/.
# Globbing keeps parallel work from colliding on hand-maintained source lists.
function(cablefit_library)
  cmake_parse_arguments(L "" "NAME;ALIAS;DIR" "DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB _srcs CONFIGURE_DEPENDS ${L_DIR}/src/*.cc)
  add_library(${L_NAME} STATIC ${_srcs})
  add_library(${L_ALIAS} ALIAS ${L_NAME})
  # Position-independent so the FreeCAD workbench's Python module can link the same libraries.
  set_target_properties(${L_NAME} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${L_NAME} PUBLIC ${L_DIR}/include PRIVATE ${L_DIR}/src)
  target_link_libraries(${L_NAME} PUBLIC ${L_DEPS} PRIVATE ${L_PRIVATE_DEPS} cablefit_warnings)
endfunction()

# cablefit_test_dir(NAME <exe> DIR <dir> LIBS ...): every *_test.cc in DIR becomes part of one
# GoogleTest executable registered with CTest test by test.
function(cablefit_test_dir)
  cmake_parse_arguments(T "" "NAME;DIR" "LIBS" ${ARGN})
  file(GLOB _srcs CONFIGURE_DEPENDS ${T_DIR}/*_test.cc)
  if(NOT _srcs)
    return()
  endif()
  add_executable(${T_NAME} ${_srcs})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} cablefit_test_support GTest::gtest_main cablefit_warnings)
  # One variable per property: gtest_discover_tests splits a ';'-list value into separate
  # arguments, which silently dropped the second variable of a single ENVIRONMENT list.
  gtest_discover_tests(${T_NAME} DISCOVERY_TIMEOUT 60 PROPERTIES
    ENVIRONMENT "CABLEFIT_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
    ENVIRONMENT_MODIFICATION "CABLEFIT_BINARY_DIR=set:${PROJECT_BINARY_DIR}")
endfunction()
