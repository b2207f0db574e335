// The WebAssembly module's extra entry points: the C API (foresight_c.h) with every struct passed
// by pointer. JavaScript can call an exported function only with numbers, so the fs_* functions
// that take or return a struct by value get a twin here that reads and writes it through a
// pointer; the others are exported as they are (build flags in CMakeLists.txt). Nothing else:
// the conversions stay in foresight_c.cpp.

#include <foresight/foresight_c.h>

#include <emscripten/emscripten.h>

#include <cstddef>
#include <cstdint>

#include <unistd.h>

extern "C" {

/// fs_predict_accelerated with the acceleration [Units: m/s^2] read through a pointer.
EMSCRIPTEN_KEEPALIVE fs_status fsw_predict_accelerated(const fs_point_state* start, const fs_vec3* acceleration,
                                                       float time, fs_point_state* out) noexcept {
    if (acceleration == nullptr) return FS_STATUS_NULL_POINTER;
    return fs_predict_accelerated(start, *acceleration, time, out);
}

/// fs_predict_projectile with the start position [Units: m] and velocity [Units: m/s] read
/// through pointers.
EMSCRIPTEN_KEEPALIVE fs_status fsw_predict_projectile(const fs_dvec3* position, const fs_vec3* velocity, float time,
                                                      const fs_projectile_settings* settings, const fs_world* world,
                                                      fs_trajectory_point* points, std::size_t capacity,
                                                      fs_projectile_result* out) noexcept {
    if (position == nullptr || velocity == nullptr) return FS_STATUS_NULL_POINTER;
    return fs_predict_projectile(*position, *velocity, time, settings, world, points, capacity, out);
}

/// Writes fs_vehicle_settings_default() to `out`.
EMSCRIPTEN_KEEPALIVE void fsw_vehicle_settings_default(fs_vehicle_settings* out) noexcept {
    if (out != nullptr) *out = fs_vehicle_settings_default();
}

/// Writes fs_projectile_settings_default() to `out`.
EMSCRIPTEN_KEEPALIVE void fsw_projectile_settings_default(fs_projectile_settings* out) noexcept {
    if (out != nullptr) *out = fs_projectile_settings_default();
}

/// Writes fs_aim_shot_default() to `out`.
EMSCRIPTEN_KEEPALIVE void fsw_aim_shot_default(fs_aim_shot* out) noexcept {
    if (out != nullptr) *out = fs_aim_shot_default();
}

/// Writes fs_dr_receiver_settings_default() to `out`.
EMSCRIPTEN_KEEPALIVE void fsw_dr_receiver_settings_default(fs_dr_receiver_settings* out) noexcept {
    if (out != nullptr) *out = fs_dr_receiver_settings_default();
}

/// fs_is_point_safe with the point [Units: m] read through a pointer.
EMSCRIPTEN_KEEPALIVE fs_status fsw_is_point_safe(const fs_trajectory_point* trajectory, std::size_t count,
                                                 const fs_projectile_danger* danger, const fs_dvec3* point, float time,
                                                 std::int32_t* safe) noexcept {
    if (point == nullptr) return FS_STATUS_NULL_POINTER;
    return fs_is_point_safe(trajectory, count, danger, *point, time, safe);
}

/// fs_find_danger_start with the point [Units: m] read through a pointer.
EMSCRIPTEN_KEEPALIVE fs_status fsw_find_danger_start(const fs_trajectory_point* trajectory, std::size_t count,
                                                     const fs_projectile_danger* danger, const fs_dvec3* point,
                                                     fs_danger_start* out) noexcept {
    if (point == nullptr) return FS_STATUS_NULL_POINTER;
    return fs_find_danger_start(trajectory, count, danger, *point, out);
}

/// fs_find_closest_path_approach with the point [Units: m] read through a pointer.
EMSCRIPTEN_KEEPALIVE fs_status fsw_find_closest_path_approach(const fs_trajectory_point* trajectory, std::size_t count,
                                                              const fs_dvec3* point, float from_time, float until_time,
                                                              fs_closest_approach* out) noexcept {
    if (point == nullptr) return FS_STATUS_NULL_POINTER;
    return fs_find_closest_path_approach(trajectory, count, *point, from_time, until_time, out);
}

/// Writes fs_vehicle_body_default() to `out`.
EMSCRIPTEN_KEEPALIVE void fsw_vehicle_body_default(fs_vehicle_body* out) noexcept {
    if (out != nullptr) *out = fs_vehicle_body_default();
}

/// Writes fs_character_body_default() to `out`.
EMSCRIPTEN_KEEPALIVE void fsw_character_body_default(fs_character_body* out) noexcept {
    if (out != nullptr) *out = fs_character_body_default();
}

/// Writes fs_approach_settings_default() to `out`.
EMSCRIPTEN_KEEPALIVE void fsw_approach_settings_default(fs_approach_settings* out) noexcept {
    if (out != nullptr) *out = fs_approach_settings_default();
}

/// The end of the heap (sbrk(0)) [Units: bytes]: the allocator takes more memory only when what it
/// freed is not enough, so a loop that frees all it allocates leaves it where it was (the package's
/// leak test).
EMSCRIPTEN_KEEPALIVE std::uint32_t fsw_heap_end() noexcept {
    return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(sbrk(0)));
}

}  // extern "C"
