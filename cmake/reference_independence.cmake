# The OSMesa reference must share only the scene model and the GLSL text with the renderer it
# checks: a reference that shares code with what it checks cannot catch that code's bugs.
#
# Included at the end of the top-level CMakeLists.txt, it walks the link closure of the
# quadshade_reference target (configure fails if a renderer library or the renderer's compiler
# flags are in it) and scans reference/'s #include lines (configure fails on any header of
# shading/, core/, raster/, raycast/, render/, regression/, generators/ or apps/). It writes the
# closure to the build folder, and the test "reference shares only the scene model and the GLSL"
# reruns both checks with `cmake -P` on the files as they are when the tests run.

set(QUADSHADE_RENDERER_DIRS shading core raster raycast render regression generators apps)

# Fails (FATAL_ERROR at configure time, or the -P script's exit code) on a forbidden #include.
function(quadshade_check_reference_includes source_dir)
    file(GLOB files "${source_dir}/reference/*.h" "${source_dir}/reference/*.cpp")
    list(JOIN QUADSHADE_RENDERER_DIRS "|" dirs)
    foreach(f IN LISTS files)
        file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include")
        foreach(line IN LISTS lines)
            if(line MATCHES "#[ \t]*include[ \t]*[<\"](${dirs})/")
                message(FATAL_ERROR "${f}: '${line}': reference/ may include the scene model (scenes/) and its own "
                                    "headers, nothing of the renderer (${dirs})")
            endif()
        endforeach()
    endforeach()
endfunction()

# Every target quadshade_reference links, directly or through others.
function(quadshade_link_closure target out)
    set(seen "")
    set(todo "${target}")
    while(todo)
        list(POP_FRONT todo t)
        if(t IN_LIST seen OR NOT TARGET "${t}")
            continue()
        endif()
        list(APPEND seen "${t}")
        get_target_property(type "${t}" TYPE)
        set(links "")
        if(NOT type STREQUAL "INTERFACE_LIBRARY")
            get_target_property(direct "${t}" LINK_LIBRARIES)
            if(direct)
                list(APPEND links ${direct})
            endif()
        endif()
        get_target_property(iface "${t}" INTERFACE_LINK_LIBRARIES)
        if(iface)
            list(APPEND links ${iface})
        endif()
        foreach(l IN LISTS links)
            string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" l "${l}")
            if(NOT l MATCHES "^::@" AND NOT l MATCHES "^\\$<")
                list(APPEND todo "${l}")
            endif()
        endforeach()
    endwhile()
    set(${out} "${seen}" PARENT_SCOPE)
endfunction()

function(quadshade_check_reference_closure closure)
    foreach(t IN LISTS closure)
        if(t MATCHES "^quadshade_(shading|core|raster|raycast|render|regression|flags)$")
            message(FATAL_ERROR "quadshade_reference links ${t}: the reference may link the scene model "
                                "(quadshade_scenes), OSMesa and its own libraries, nothing of the renderer "
                                "(link closure: ${closure})")
        endif()
    endforeach()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE)
    # The test: SOURCE_DIR and CLOSURE_FILE given with -D.
    quadshade_check_reference_includes("${SOURCE_DIR}")
    file(READ "${CLOSURE_FILE}" closure)
    quadshade_check_reference_closure("${closure}")
    message(STATUS "reference/ includes and links nothing of the renderer; link closure: ${closure}")
else()
    quadshade_check_reference_includes("${PROJECT_SOURCE_DIR}")
    quadshade_link_closure(quadshade_reference closure)
    quadshade_check_reference_closure("${closure}")
    file(WRITE "${CMAKE_BINARY_DIR}/reference-link-closure.txt" "${closure}")
endif()
