# Installs Tessel into a scratch prefix and builds a classic C program the way a user of a
# libGL/libglut replacement would:  cc prog.c $(pkg-config --cflags --libs tessel-glut)
# (or PACKAGE, e.g. tessel-glfw), then runs it headless and checks that it wrote its frame.
#   cmake -DBUILD=<build dir> -DOUT=<scratch dir> -DPROGRAM=<prog.c> [-DPACKAGE=tessel-glfw]
#         [-DINCLUDE=<dir the program's own headers are in>] -P pkgconfig.cmake
if(NOT PACKAGE)
  set(PACKAGE tessel-glut)
endif()
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${OUT}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed:\n${err}")
endif()
file(GLOB_RECURSE pcs "${OUT}/prefix/*/${PACKAGE}.pc")
list(GET pcs 0 pc)
get_filename_component(pcdir "${pc}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} "${pcdir}")
execute_process(COMMAND pkg-config --cflags --libs ${PACKAGE} RESULT_VARIABLE rc OUTPUT_VARIABLE flags
                ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config --cflags --libs ${PACKAGE} failed:\n${err}")
endif()
separate_arguments(flag_list UNIX_COMMAND "${flags}")
if(INCLUDE)
  list(PREPEND flag_list "-I${INCLUDE}")
endif()
execute_process(COMMAND cc -std=c99 "${PROGRAM}" ${flag_list} -lm -o "${OUT}/prog"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cc ${PROGRAM} ${flags} failed:\n${out}${err}")
endif()
set(ENV{TESSEL_HEADLESS} "frames:1,out:${OUT}/frames")
unset(ENV{DISPLAY})
execute_process(COMMAND "${OUT}/prog" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT rc EQUAL 0 OR NOT EXISTS "${OUT}/frames/frame-0000.png")
  message(FATAL_ERROR "the program built with pkg-config did not run (${rc}):\n${out}${err}")
endif()
message(STATUS "cc prog.c ${flags}: built, ran, wrote ${OUT}/frames/frame-0000.png")
