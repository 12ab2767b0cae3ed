# `tessel render` with 1, 2 and 8 threads must write byte-identical PNGs.
# Run as: cmake -DTESSEL=<path> -DOUT=<dir> -P threads_identical.cmake
file(MAKE_DIRECTORY ${OUT})
foreach(n 1 2 8)
  execute_process(COMMAND ${TESSEL} render --size 640x360 --threads ${n} -o ${OUT}/demo-${n}.png
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "tessel render --threads ${n} failed (${rc}): ${err}")
  endif()
  message(STATUS "${out}")
endforeach()
foreach(n 2 8)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/demo-1.png ${OUT}/demo-${n}.png RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "--threads 1 and --threads ${n} wrote different PNGs")
  endif()
endforeach()
message(STATUS "threads 1, 2, 8: identical")
