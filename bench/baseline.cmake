# bench_baseline: the accuracy–cost benchmark's two baselines (bench/baseline.h): the seed shader as
# written and with its formula errors fixed (plain Riemann sum), over postfx's medium and FogUniforms.
# An include()-able snippet (bench/CMakeLists.txt includes it); needs demo_host (POSTFX_BUILD_DEMO).
# The bench is a host: it links the Vulkan loader and calls vk* directly; it also reaches postfx's
# internal headers (postfx/src: fog/fog_uniforms.h for buildUniforms, core/checks.h).
add_library(bench_baseline STATIC ${PROJECT_SOURCE_DIR}/bench/baseline.cpp)
target_include_directories(bench_baseline
    PUBLIC ${PROJECT_SOURCE_DIR}/bench ${PROJECT_SOURCE_DIR}/demo
    PRIVATE ${PROJECT_SOURCE_DIR}/postfx/src ${PROJECT_SOURCE_DIR}/shaders)
target_link_libraries(bench_baseline PUBLIC postfx_internal demo_host Vulkan::Vulkan)
postfx_embed_shaders(bench_baseline NAMESPACE bench::spirv SOURCE_DIR ${PROJECT_SOURCE_DIR}
    SHADERS bench/shaders/seed_as_written.comp bench/shaders/seed_fixed_riemann.comp
    INCLUDE_DIRS ${PROJECT_SOURCE_DIR}/shaders ${PROJECT_SOURCE_DIR}/bench/shaders)
