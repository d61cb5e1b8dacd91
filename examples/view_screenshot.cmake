# cmake -DXVFB_RUN=<xvfb-run> -DVIEW=<view> -DCHECK=<side_colours> -DINPUT=<mesh>
#       -DPICTURE=<png> -DSIDES=both|front|ramp [-DOPTIONS=<a;b;...>] -P view_screenshot.cmake
#
# Takes a picture of INPUT with the view tool (and its OPTIONS) on a virtual
# 24-bit screen and checks that it shows both sides' colours, the front's
# only, or both ends of the colour ramp of --scalar (side_colours).
file(REMOVE ${PICTURE})
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${VIEW} ${INPUT} ${OPTIONS} --screenshot ${PICTURE}
                RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status EQUAL 0 OR NOT _out MATCHES "^\\{\"screenshot\":\"[^\n]+\\}\n$")
  message(FATAL_ERROR "view exited with '${_status}'; stdout: ${_out}; stderr: ${_err}")
endif()
execute_process(COMMAND ${CHECK} ${PICTURE} ${SIDES} RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "${PICTURE} does not show ${SIDES} side(s) as expected: ${_out}${_err}")
endif()
message(STATUS "${PICTURE}: ${_out}")
