/* article_scenarios.c: the C API's twin of article_scenarios.cpp. It must print exactly the same
 * text (CTest compares the two): the reference article's three scenarios, numbers with 6
 * decimals. Metres, seconds, radians; +Y up, +Z forward. */

#include <foresight/foresight_c.h>

#include <stdio.h>

static void number(double value) { printf("%.6f", value + 0.0); /* + 0.0: -0 prints as 0 */ }

static void vec(const char* label, double x, double y, double z) {
    printf("%s (", label);
    number(x);
    printf(", ");
    number(y);
    printf(", ");
    number(z);
    printf(")");
}

static void vecf(const char* label, fs_vec3 v) { vec(label, v.x, v.y, v.z); }
static void vecd(const char* label, fs_dvec3 v) { vec(label, v.x, v.y, v.z); }

static int ok(fs_status status, const char* what) {
    if (status == FS_STATUS_OK) return 1;
    fprintf(stderr, "%s: %s\n", what, fs_status_message(status));
    return 0;
}

static int character(void) {
    fs_point_state now = {{1.0, 0.0, 2.0}, {3.0f, 0.0f, 4.0f}, 0.0f};
    fs_vec3 acceleration = {0.0f, 0.0f, -2.0f};
    fs_point_state linear, accelerated;
    if (!ok(fs_predict_linear(&now, 0.5f, &linear), "predictLinear")) return 0;
    if (!ok(fs_predict_accelerated(&now, acceleration, 0.5f, &accelerated), "predictAccelerated")) return 0;
    printf("character\n");
    vecd("  linear      position", linear.position);
    vecf(" velocity", linear.velocity);
    printf("\n");
    vecd("  accelerated position", accelerated.position);
    vecf(" velocity", accelerated.velocity);
    printf("\n");
    return 1;
}

enum { kCapacity = 4096 };
static fs_trajectory_point trajectory[kCapacity];

static int grenade(const char* name, const fs_projectile_settings* settings, const fs_world* world) {
    fs_dvec3 hand = {0.0, 1.6f, 0.0}; /* 1.6f: the C++ program's RVec3(0, 1.6f, 0) */
    fs_vec3 velocity = {0.0f, 4.0f, 12.0f};
    fs_projectile_result result;
    int shown = 0;
    size_t i;
    if (!ok(fs_predict_projectile(hand, velocity, 3.0f, settings, world, trajectory, kCapacity, &result), name))
        return 0;
    printf("grenade %s: %u bounces, %llu points\n", name, result.bounces, (unsigned long long)result.trajectory_size);
    for (i = 0; i < result.trajectory_size; ++i) {
        const fs_trajectory_point* point = &trajectory[i];
        if (point->event != FS_EVENT_BOUNCE || shown == 3) continue;
        ++shown;
        printf("  bounce t ");
        number(point->time);
        vecd(" position", point->position);
        vecf(" normal", point->normal);
        printf("\n");
    }
    printf("  end    t ");
    number(result.time);
    vecd(" position", result.position);
    vecf(" velocity", result.velocity);
    printf("%s\n", result.at_rest ? " at rest" : "");
    return 1;
}

static int grenades(void) {
    fs_plane floor_plane = {{0.0f, 1.0f, 0.0f}, 0.0f, 0.0};
    fs_box wall = {{0.0, 1.5, 10.0}, {5.0f, 1.5f, 0.25f}, {0.0f, 0.0f, 0.0f, 1.0f}, 0.0f};
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_world* world = fs_world_create();
    int all = world != NULL && ok(fs_world_add_plane(world, &floor_plane, NULL), "add floor") &&
              ok(fs_world_add_box(world, &wall, NULL), "add wall");
    settings.restitution = 0.5f;
    settings.friction = 0.4f;
    settings.radius = 0.05f;
    settings.method = FS_METHOD_STEPPED;
    all = all && grenade("stepped", &settings, world);
    settings.method = FS_METHOD_EXACT;
    all = all && grenade("exact", &settings, world);
    settings.method = FS_METHOD_ENGINE;
    settings.engine = FS_ENGINE_JOLT;
    all = all && grenade("jolt", &settings, world);
    fs_world_destroy(world);
    return all;
}

static void vehicle(const char* label, const fs_vehicle_state* state) {
    vecd(label, state->position);
    vecf(" velocity", state->velocity);
    printf(" orientation (");
    number(state->orientation.w);
    printf(", ");
    number(state->orientation.x);
    printf(", ");
    number(state->orientation.y);
    printf(", ");
    number(state->orientation.z);
    printf(")\n");
}

static int car(void) {
    fs_vehicle_state start = {{0.0, 0.0, 0.0}, {0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.5f, 0.0f}};
    fs_vehicle_settings settings = fs_vehicle_settings_default();
    fs_vehicle_state iterated, exact;
    if (!ok(fs_predict_vehicle_iterative(&start, 2.0f, 4, &settings, &iterated), "predictVehicleIterative")) return 0;
    if (!ok(fs_predict_vehicle_exact(&start, 2.0f, &settings, &exact), "predictVehicleExact")) return 0;
    printf("car\n");
    vehicle("  iterative", &iterated);
    vehicle("  exact    ", &exact);
    return 1;
}

int main(void) { return character() && grenades() && car() ? 0 : 1; }
