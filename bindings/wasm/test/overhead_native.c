/* overhead_native.c: the native side of the WebAssembly package's overhead figure. Times the
 * scenarios of examples/overhead.mjs through the native C API (the C++ library behind a plain
 * call) and prints microseconds per prediction, the best of 5 rounds.
 *
 *   build/bindings/wasm/foresight_wasm_overhead_native */

#include <foresight/foresight_c.h>

#include <stdio.h>
#include <time.h>

static double now(void) {
    struct timespec t;
    timespec_get(&t, TIME_UTC);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

enum { kCapacity = 4096 };
static fs_trajectory_point points[kCapacity];

static double best(const fs_projectile_settings* s, const fs_world* world, float time, size_t capacity, int n) {
    fs_dvec3 hand = {0.0, 1.6f, 0.0};
    fs_vec3 velocity = {0.0f, 4.0f, 12.0f};
    fs_projectile_result r;
    double fastest = 1e30, sink = 0.0;
    int round, i;
    for (round = 0; round < 5; ++round) {
        double start = now(), elapsed;
        for (i = 0; i < n; ++i) {
            fs_predict_projectile(hand, velocity, time, s, world, points, capacity, &r);
            sink += r.position.z;
        }
        elapsed = (now() - start) / n * 1e6;
        if (elapsed < fastest) fastest = elapsed;
    }
    if (sink == 0.0) printf("?");
    return fastest;
}

int main(void) {
    fs_plane floor_plane = {{0.0f, 1.0f, 0.0f}, 0.0f, 0.0};
    fs_box wall = {{0.0, 1.5, 10.0}, {5.0f, 1.5f, 0.25f}, {0.0f, 0.0f, 0.0f, 1.0f}, 0.0f};
    fs_projectile_settings s = fs_projectile_settings_default();
    fs_world* world = fs_world_create();
    if (world == NULL || fs_world_add_plane(world, &floor_plane, NULL) != FS_STATUS_OK ||
        fs_world_add_box(world, &wall, NULL) != FS_STATUS_OK)
        return 1;
    printf("free flight 0.5 s, no trajectory: %.3f us\n", best(&s, NULL, 0.5f, 0, 200000));
    s.restitution = 0.5f;
    s.friction = 0.4f;
    s.radius = 0.05f;
    printf("article grenade, exact, 3 s, with trajectory: %.3f us\n", best(&s, world, 3.0f, kCapacity, 5000));
    s.method = FS_METHOD_ENGINE;
    printf("article grenade, jolt, 3 s, with trajectory: %.3f us\n", best(&s, world, 3.0f, kCapacity, 5000));
    fs_world_destroy(world);
    return 0;
}
