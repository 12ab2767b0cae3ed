# `tessel render -o out/new/dir/x.png` makes the folders on the way, and a GLSL twin renders.
# Run as: cmake -DTESSEL=<path> -DOUT=<dir> -P makes_folders.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${TESSEL} render --size 64x36 -o ${OUT}/new/dir/x.png RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/new/dir/x.png)
  message(FATAL_ERROR "tessel render -o ${OUT}/new/dir/x.png failed (${rc}): ${err}")
endif()
execute_process(COMMAND ${TESSEL} render ${SCENE} --shading glsl-phong --size 64x36 -o ${OUT}/glsl/twin.png
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/glsl/twin.png)
  message(FATAL_ERROR "tessel render --shading glsl-phong failed (${rc}): ${err}")
endif()
message(STATUS "folders made; the GLSL twin rendered")
