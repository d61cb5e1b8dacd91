# Installs the project into a scratch prefix, then configures and builds the
# consumer against it, and runs it. Arguments: -DSOURCE_DIR -DBINARY_DIR
# -DWORK_DIR -DEXPECT_PARALLEL (the package was built with TBB: the consumer
# must get parallel subdivision without asking for TBB itself)
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BINARY_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/test/install_consumer" -B "${WORK_DIR}/build"
                        "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix"
                        # A Debug build at -O0 without debug information (CGAL's assertions
                        # on): what is tested is the package, and optimising CGAL's
                        # templates would triple the time of the test.
                        -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0
                        "-DEXPECT_PARALLEL=${EXPECT_PARALLEL}"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "find_package(CGAL_ext) from the install prefix failed")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK_DIR}/build" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer does not build against the installed headers")
endif()
execute_process(COMMAND "${WORK_DIR}/build/consumer" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer failed (exit status ${rc})")
endif()
