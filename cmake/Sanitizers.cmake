# The sanitizer build (POSTFX_SANITIZE, top-level only; scripts/run-sanitizer-tests.sh): the root
# CMakeLists.txt compiles and links every target with -fsanitize=<list>; this links every executable
# of the project with tests/sanitizers/keep_modules_loaded.cpp (shared libraries stay loaded until
# exit, so that LeakSanitizer names the driver or layer that leaked). Included after every folder.
add_library(postfx_keep_modules_loaded OBJECT ${PROJECT_SOURCE_DIR}/tests/sanitizers/keep_modules_loaded.cpp)

function(postfx_link_keep_modules_loaded dir)
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
        get_target_property(type ${target} TYPE)
        if(type STREQUAL "EXECUTABLE")
            target_link_libraries(${target} PRIVATE postfx_keep_modules_loaded)
        endif()
    endforeach()
    get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    foreach(subdir IN LISTS subdirs)
        postfx_link_keep_modules_loaded(${subdir})
    endforeach()
endfunction()
postfx_link_keep_modules_loaded(${PROJECT_SOURCE_DIR})
