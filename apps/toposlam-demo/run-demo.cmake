# The TopoSLAM demo: the whole pipeline on the bundled simulated office log, with the commands
# a user would type. Run by `cmake --build --preset demo` (target `demo`), or directly:
#   cmake -DBIN=build/release/bin -DSOURCE=. -DOUT=build/release/demo -P apps/toposlam-demo/run-demo.cmake
foreach(var BIN SOURCE OUT)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "run-demo.cmake needs -D${var}=...")
    endif()
endforeach()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")

function(step title)
    message(STATUS "")
    message(STATUS "=== ${title}")
    list(JOIN ARGN " " shown)
    string(REPLACE "${BIN}/" "" shown "${shown}")
    string(REPLACE "${SOURCE}/" "" shown "${shown}")
    message(STATUS "$ ${shown}")
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "demo step failed (exit ${rc}): ${shown}")
    endif()
endfunction()

set(log "${SOURCE}/share/office/office.rawlog")
step("1. SLAM: laser + odometry log -> trajectory + occupancy grid"
     "${BIN}/toposlam-slam" "${SOURCE}/config_ini/toposlam-slam.ini" "${log}" -o "${OUT}/slam")
step("2. accuracy of the SLAM trajectory against the simulator's ground truth"
     "${BIN}/toposlam-eval-slam" "${OUT}/slam/trajectory.txt" --name toposlam-slam
     --odometry-of "${log}"
     --ground-truth "${SOURCE}/share/office/office_gt.txt" --json "${OUT}/slam/accuracy.json")
step("3. rooms and doors: virtual-door segmentation of the grid, along the robot's path"
     "${BIN}/toposlam-rooms" "${OUT}/slam/map.gridmap.gz" --trajectory "${OUT}/slam/trajectory.txt"
     -c "${SOURCE}/config_ini/rooms.ini" -o "${OUT}/rooms")
step("4. a room-to-room path: from room 1 to the room farthest from it"
     "${BIN}/toposlam-plan" "${OUT}/slam/map.gridmap.gz" "${OUT}/rooms/rooms.json"
     --from 1 --to farthest -o "${OUT}/plan")

message(STATUS "")
message(STATUS "=== Output files")
file(GLOB_RECURSE outputs RELATIVE "${OUT}" "${OUT}/*")
list(SORT outputs)
foreach(f IN LISTS outputs)
    file(SIZE "${OUT}/${f}" size)
    message(STATUS "  ${OUT}/${f}  (${size} bytes)")
endforeach()
message(STATUS "Look at: ${OUT}/slam/map.png, ${OUT}/rooms/rooms.png, ${OUT}/plan/path.png")
