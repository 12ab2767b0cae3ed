# `tessel bench` on every standard scene: the images are byte-identical for 1, 2 and 8
# threads, and the JSON has one object per run with the documented keys.
# Run as: cmake -DTESSEL=<path> -DOUT=<dir> -P bench_scenes.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${TESSEL} bench --size 200x120 --threads 1 --threads 2 --threads 8 --frames 1 --warmup 0
                        --images ${OUT} --json ${OUT}/bench.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tessel bench failed (${rc}): ${out} ${err}")
endif()
message(STATUS "${out}")
foreach(scene spheres-100k spheres-1m fill textured fixed-100k)
  foreach(n 2 8)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/${scene}_200x120_t1.png ${OUT}/${scene}_200x120_t${n}.png
                    RESULT_VARIABLE same)
    if(NOT same EQUAL 0)
      message(FATAL_ERROR "${scene}: --threads 1 and --threads ${n} wrote different images")
    endif()
  endforeach()
endforeach()
file(READ ${OUT}/bench.json json)
string(JSON runs LENGTH "${json}")
if(NOT runs EQUAL 15)
  message(FATAL_ERROR "bench.json has ${runs} runs, expected 15")
endif()
foreach(key scene width height threads ms_median mtris_s mpix_s peak_rss_mb image)
  string(JSON value ERROR_VARIABLE missing GET "${json}" 0 ${key})
  if(missing)
    message(FATAL_ERROR "bench.json: key '${key}' missing")
  endif()
endforeach()
message(STATUS "5 scenes x threads 1, 2, 8: identical images; JSON complete")
