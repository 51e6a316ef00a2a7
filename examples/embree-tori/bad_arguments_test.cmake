# SPDX-License-Identifier: Apache-2.0
# Embree.ExampleRejectsBadArguments: each bad command line gets a message
# naming the problem and a non-zero exit, and leaves no file behind.
#   cmake -DEXAMPLE=... -DOUT=dir -P bad_arguments_test.cmake
foreach(var EXAMPLE OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "bad_arguments_test.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}/a-folder.png")
set(good "${OUT}/out.png")

# The expected exit code, a regular expression for stderr, the arguments.
function(expect_failure want_rc want_err)
  execute_process(COMMAND "${EXAMPLE}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc STREQUAL want_rc OR NOT err MATCHES "${want_err}")
    message(SEND_ERROR "embree-tori ${ARGN}: exit ${rc} (want ${want_rc}), stderr: ${err}(want /${want_err}/)")
  else()
    string(REGEX REPLACE "\n.*" "" first "${err}")
    message(STATUS "ok, exit ${rc}: ${first}")
  endif()
endfunction()

expect_failure(2 "--width must be a whole number from 1 to 8192, got '0'" --width 0 -o ${good})
expect_failure(2 "--width must be a whole number from 1 to 8192, got 'abc'" --width abc -o ${good})
expect_failure(2 "--height must be a whole number from 1 to 8192, got '12x'" --height 12x -o ${good})
expect_failure(2 "--height must be a whole number from 1 to 8192, got '-5'" --height=-5 -o ${good})
expect_failure(2 "--width must be a whole number from 1 to 8192, got '99999999999'" --width 99999999999 -o ${good})
expect_failure(2 "--width must be a whole number from 1 to 8192, got '8193'" --width 8193 -o ${good})
expect_failure(2 "--width needs a value" -o ${good} --width)
expect_failure(2 "unknown option '--bogus'" --bogus -o ${good})
expect_failure(2 "unknown option 'extra'" extra -o ${good})
expect_failure(2 "the output must be a .png file, got '.*out.ppm'" -o ${OUT}/out.ppm)
expect_failure(2 "the output path is empty" --output=)
expect_failure(1 "cannot write '.*no-such-folder/x.png': No such file or directory"
  -o ${OUT}/no-such-folder/x.png --width 8 --height 8)
expect_failure(1 "cannot write '.*a-folder.png': Is a directory" -o ${OUT}/a-folder.png --width 8 --height 8)

# Nothing was written: no image, no temporary.
file(GLOB left "${OUT}/*")
list(REMOVE_ITEM left "${OUT}/a-folder.png")
if(left)
  message(SEND_ERROR "files left behind: ${left}")
endif()
file(GLOB left_in_folder "${OUT}/a-folder.png/*")
if(left_in_folder)
  message(SEND_ERROR "files left behind: ${left_in_folder}")
endif()
# --help succeeds and writes nothing.
execute_process(COMMAND "${EXAMPLE}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "usage: embree-tori")
  message(SEND_ERROR "--help: exit ${rc}, output ${out}")
endif()
