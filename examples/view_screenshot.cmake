# cmake -DXVFB_RUN=<xvfb-run> -DVIEW=<view> -DCHECK=<side_colours> -DINPUT=<mesh>
#       -DPICTURE=<png> -DSIDES=both|front|ramp|high|checker [-DOPTIONS=<a;b;...>] [-DEXPECT=<regex>]
#       -P view_screenshot.cmake
#
# Takes a picture of INPUT with the view tool (and its OPTIONS) on a virtual
# 24-bit screen and checks that it shows both sides' colours, the front's
# only, both ends of the colour ramp of --scalar (or its upper end only), or both colours of
# --uv-checker (side_colours); with EXPECT, that its JSON line matches.
file(REMOVE ${PICTURE})
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x1024x24" ${VIEW} ${INPUT} ${OPTIONS} --screenshot ${PICTURE}
                RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status EQUAL 0 OR NOT _out MATCHES "^\\{\"screenshot\":\"[^\n]+\\}\n$")
  message(FATAL_ERROR "view exited with '${_status}'; stdout: ${_out}; stderr: ${_err}")
endif()
if(DEFINED EXPECT AND NOT _out MATCHES "${EXPECT}")
  message(FATAL_ERROR "view's line does not match '${EXPECT}': ${_out}")
endif()
execute_process(COMMAND ${CHECK} ${PICTURE} ${SIDES} RESULT_VARIABLE _status OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _status EQUAL 0)
  message(FATAL_ERROR "${PICTURE} does not show ${SIDES} side(s) as expected: ${_out}${_err}")
endif()
message(STATUS "${PICTURE}: ${_out}")
