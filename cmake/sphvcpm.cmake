# One-line declarations of libraries, applications and tests, so that each
# CMakeLists.txt reads like OpenFOAM's Make/files + Make/options.

# sphvcpm_add_library(core SOURCES a.C b.C DEPENDS other LIBS Eigen3::Eigen)
function(sphvcpm_add_library name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;LIBS" ${ARGN})
    add_library(sphvcpm_${name} STATIC ${ARG_SOURCES})
    target_include_directories(sphvcpm_${name} PUBLIC
        ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR})
    foreach(dep ${ARG_DEPENDS})
        target_link_libraries(sphvcpm_${name} PUBLIC sphvcpm_${dep})
    endforeach()
    target_link_libraries(sphvcpm_${name} PUBLIC ${ARG_LIBS})
    target_compile_options(sphvcpm_${name} PRIVATE
        $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra>)
endfunction()

# sphvcpm_add_application(generateParticles SOURCES generateParticles.C DEPENDS core)
function(sphvcpm_add_application name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;LIBS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    foreach(dep ${ARG_DEPENDS})
        target_link_libraries(${name} PRIVATE sphvcpm_${dep})
    endforeach()
    target_link_libraries(${name} PRIVATE ${ARG_LIBS})
    target_compile_options(${name} PRIVATE
        $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra>)
    set_target_properties(${name} PROPERTIES
        RUNTIME_OUTPUT_DIRECTORY ${SPHVCPM_APPBIN})
endfunction()

# sphvcpm_add_test(dictionary SOURCES testDictionary.C DEPENDS core)
# builds test_<name> with GoogleTest and registers it with CTest; tests
# run from tests/ in the source tree so they find their data files.
function(sphvcpm_add_test name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;LIBS" ${ARGN})
    add_executable(test_${name} ${ARG_SOURCES})
    foreach(dep ${ARG_DEPENDS})
        target_link_libraries(test_${name} PRIVATE sphvcpm_${dep})
    endforeach()
    target_link_libraries(test_${name} PRIVATE sphvcpm_testMain ${ARG_LIBS})
    target_compile_definitions(test_${name} PRIVATE
        SPHVCPM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
        SPHVCPM_TEST_DATA="${PROJECT_SOURCE_DIR}/tests/data")
    add_test(NAME ${name} COMMAND test_${name})
    # A test binary whose every test skipped itself (no GPU, no OpenFOAM)
    # exits 77 (tests/unit/testMain.C): skipped. Matching gtest's
    # "[  SKIPPED ]" instead would hide the failures of a binary that also
    # skipped one test. Threads sleep rather than spin at barriers: CTest
    # runs tests side by side, and spinning OpenMP threads of two processes
    # sharing the cores slow both down several times over.
    set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77
        ENVIRONMENT "OMP_WAIT_POLICY=passive")
endfunction()

# sphvcpm_add_script_test(name script.sh [args...] [THREADS n] [COST s]): a shell test; exit
# 77 = skipped. The applications it runs use one OpenMP thread unless THREADS
# says more; CTest then reserves that many cores for it (PROCESSORS), so
# that tests run side by side never ask for more threads than there are
# cores (oversubscribed OpenMP runs several times slower).
function(sphvcpm_add_script_test name script)
    cmake_parse_arguments(ARG "" "THREADS;COST" "" ${ARGN})
    if(NOT ARG_THREADS)
        set(ARG_THREADS 1)
    endif()
    add_test(NAME ${name} COMMAND bash ${script} ${ARG_UNPARSED_ARGUMENTS}
        WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77
        PROCESSORS ${ARG_THREADS}
        ENVIRONMENT "SPHVCPM_DIR=${PROJECT_SOURCE_DIR};SPHVCPM_APPBIN=${SPHVCPM_APPBIN};SPHVCPM_TESTBIN=${SPHVCPM_TESTBIN};PATH=${SPHVCPM_APPBIN}:${PROJECT_SOURCE_DIR}/bin:$ENV{PATH};OMP_NUM_THREADS=${ARG_THREADS};OMP_WAIT_POLICY=passive")
    # COST: seconds on one core, so that a first run (no timing history)
    # starts the longest tests first.
    if(ARG_COST)
        set_tests_properties(${name} PROPERTIES COST ${ARG_COST})
    endif()
endfunction()
