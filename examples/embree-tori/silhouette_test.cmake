# SPDX-License-Identifier: Apache-2.0
# Embree.SilhouetteMatchesToroidRender: `toroid render` of embree-tori.yaml
# and the Embree example, at the same size, must show a torus in the same
# pixels.
#   cmake -DTOROID=... -DEXAMPLE=... -DCOMPARE=... -DSCENE=... -DOUT=dir
#         -DWIDTH=w -DHEIGHT=h -P silhouette_test.cmake
foreach(var TOROID EXAMPLE COMPARE SCENE OUT WIDTH HEIGHT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "silhouette_test.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(MAKE_DIRECTORY "${OUT}")
set(toroid_png "${OUT}/toroid-render.png")
set(embree_png "${OUT}/embree-tori.png")
file(REMOVE "${toroid_png}" "${embree_png}")

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${what}: ${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (exit ${rc})")
  endif()
endfunction()

run_step("toroid render" "${TOROID}" render "${SCENE}" -o "${toroid_png}" --width ${WIDTH} --height ${HEIGHT} --quiet)
run_step("embree-tori" "${EXAMPLE}" --width ${WIDTH} --height ${HEIGHT} -o "${embree_png}")
run_step("silhouette-compare" "${COMPARE}" "${toroid_png}" "${embree_png}")
