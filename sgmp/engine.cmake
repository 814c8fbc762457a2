# --- SGMP packing engine: arrangements, the protocol, whole packs; the `sgmp` CLI. -----
add_library(sgmp_engine
    src/engine/colour_bins.cpp
    src/engine/size_modes.cpp
    src/engine/arrangement.cpp
    src/engine/settled_grid.cpp
    src/engine/protocol_params.cpp
    src/engine/free_arcs.cpp
    src/engine/protocol.cpp
    src/engine/contact_model.cpp
    src/engine/rolling.cpp
    src/engine/relax_params.cpp
    src/engine/neighbour_list.cpp
    src/engine/relax.cpp
    src/engine/hard_sphere_finish.cpp
    src/engine/make_pack.cpp
    src/engine/pack_checks.cpp)
target_include_directories(sgmp_engine PUBLIC include)
target_link_libraries(sgmp_engine PUBLIC sgmp_pack PRIVATE sgmp_warnings)

add_executable(sgmp app/main.cpp app/config_file.cpp)
target_link_libraries(sgmp PRIVATE sgmp_engine sgmp_pack CLI11::CLI11 sgmp_warnings)
