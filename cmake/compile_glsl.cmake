# Compiles one GLSL shader to SPIR-V as a C array header; any glslang warning fails the build.
# Invoked by postfx_embed_shaders() with -DGLSLANG=... -DSRC=... -DOUT=... -DVAR=... -DINCLUDES=a;b -DDEPFILE=...
# and optionally -DDEFINE=NAME (a variant compiled with -DNAME; NAME+OTHER: -DNAME -DOTHER).
set(include_args "")
foreach(dir IN LISTS INCLUDES)
    list(APPEND include_args "-I${dir}")
endforeach()
if(DEFINE)
    string(REPLACE "+" ";" defines "${DEFINE}")
    foreach(d IN LISTS defines)
        list(APPEND include_args "-D${d}")
    endforeach()
endif()
execute_process(
    COMMAND "${GLSLANG}" -V --target-env vulkan1.0 ${include_args} --depfile "${DEPFILE}"
            --vn "${VAR}" -o "${OUT}.tmp" "${SRC}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
# glslangValidator prints the file name on its first line even when all is well.
get_filename_component(src_name "${SRC}" NAME)
string(REPLACE "${SRC}\n" "" out "${out}")
string(REPLACE "${src_name}\n" "" out "${out}")
string(STRIP "${out}${err}" messages)
if(NOT rc EQUAL 0 OR NOT messages STREQUAL "")
    file(REMOVE "${OUT}.tmp")
    message(FATAL_ERROR "glslang on ${SRC} (warnings are errors):\n${messages}")
endif()
file(RENAME "${OUT}.tmp" "${OUT}")
# glslang names the file it wrote (OUT.tmp) as the depfile's target; the build's output is OUT, and a
# depfile naming another target leaves OUT out of date with nothing: an edited include did not rebuild.
file(READ "${DEPFILE}" deps)
string(REPLACE "${OUT}.tmp:" "${OUT}:" deps "${deps}")
file(WRITE "${DEPFILE}" "${deps}")
