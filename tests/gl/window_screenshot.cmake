# One examples/classic program in a real window: under Xvfb, the program runs with a display
# (an SDL2 window), and x11_window_check takes screenshots until the picture the same program
# renders headless appears on the screen.
#   cmake -DEXE=... -DCHECK=... -DOUT=... -P window_screenshot.cmake
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}/headless")
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(STATUS "GL-TEST-SKIPPED: xvfb-run is not installed")
  return()
endif()
set(ENV{TESSEL_HEADLESS} "frames:1,out:${OUT}/headless")
execute_process(COMMAND "${EXE}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT rc EQUAL 0 OR NOT EXISTS "${OUT}/headless/frame-0000.png")
  message(FATAL_ERROR "headless run of ${EXE} failed (${rc}):\n${out}${err}")
endif()
unset(ENV{TESSEL_HEADLESS})
set(script "\"${EXE}\" & pid=$!; \"${CHECK}\" \"${OUT}/headless/frame-0000.png\" \"${OUT}/screen.png\" --timeout 20; rc=$?; kill $pid 2>/dev/null; wait $pid 2>/dev/null; exit $rc")
execute_process(COMMAND "${XVFB_RUN}" -a -s "-screen 0 1024x768x24" sh -c "${script}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 90)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXE} in a window under Xvfb: ${out}${err} (screenshot: ${OUT}/screen.png)")
endif()
message(STATUS "${out}")
