/* native_reference.c: prints, as JSON, what the native C API computes for a set of projectile,
 * vehicle, aim and dead-reckoning inputs (the inputs too). The WebAssembly package's api and
 * netcode tests repeat every call through JavaScript and require the same numbers bit for bit:
 * doubles are printed with 17 significant digits and floats widened to double, both of which
 * read back exactly. */

#include <foresight/foresight_c.h>

#include <stdio.h>

static void d(double value) { printf("%.17g", value); }

static void dvec(fs_dvec3 v) {
    printf("[");
    d(v.x);
    printf(",");
    d(v.y);
    printf(",");
    d(v.z);
    printf("]");
}

static void fvec(fs_vec3 v) {
    printf("[");
    d(v.x);
    printf(",");
    d(v.y);
    printf(",");
    d(v.z);
    printf("]");
}

static void fquat(fs_quat q) {
    printf("[");
    d(q.x);
    printf(",");
    d(q.y);
    printf(",");
    d(q.z);
    printf(",");
    d(q.w);
    printf("]");
}

enum { kCapacity = 8192 };
static fs_trajectory_point points[kCapacity];

static const char* const kMethods[] = {"exact", "stepped", "engine"};
static const char* const kEngines[] = {"custom", "jolt",   "physx",        "rapier",
                                       "bullet", "godot3", "godot3Bullet", "box2d"};

static int projectile(int first, fs_dvec3 position, fs_vec3 velocity, float time, const fs_projectile_settings* s,
                      const fs_world* world) {
    fs_projectile_result r;
    size_t i;
    fs_status status = fs_predict_projectile(position, velocity, time, s, world, points, kCapacity, &r);
    printf("%s\n{\"position\":", first ? "" : ",");
    dvec(position);
    printf(",\"velocity\":");
    fvec(velocity);
    printf(",\"time\":");
    d(time);
    printf(",\"world\":%s,\"settings\":{\"method\":\"%s\",\"engine\":\"%s\",\"gravity\":", world ? "true" : "false",
           kMethods[s->method], kEngines[s->engine]);
    fvec(s->gravity);
    printf(",\"step\":");
    d(s->step);
    printf(",\"restitution\":");
    d(s->restitution);
    printf(",\"friction\":");
    d(s->friction);
    printf(",\"radius\":");
    d(s->radius);
    printf(",\"maxBounces\":%u},\"status\":%d", s->max_bounces, status);
    if (status != FS_STATUS_OK) {
        printf("}");
        return 1; /* a refusal is compared too */
    }
    printf(",\"result\":{\"position\":");
    dvec(r.position);
    printf(",\"velocity\":");
    fvec(r.velocity);
    printf(",\"time\":");
    d(r.time);
    printf(",\"bounces\":%u,\"atRest\":%s,\"stoppedAtHit\":%s,\"hitNormal\":", r.bounces, r.at_rest ? "true" : "false",
           r.stopped_at_hit ? "true" : "false");
    fvec(r.hit_normal);
    printf("},\"trajectory\":[");
    for (i = 0; i < r.trajectory_size; ++i) {
        printf("%s[", i ? "," : "");
        d(points[i].time);
        printf(",%d,", points[i].event);
        dvec(points[i].position);
        printf(",");
        fvec(points[i].velocity);
        printf(",");
        fvec(points[i].normal);
        printf("]");
    }
    printf("]}");
    return r.trajectory_size == r.trajectory_needed;
}

static void vehicle(int first, const fs_vehicle_state* start, float time, int32_t iterations, int32_t frame) {
    fs_vehicle_settings settings = fs_vehicle_settings_default();
    fs_vehicle_state iterated, exact;
    settings.frame = frame;
    fs_predict_vehicle_iterative(start, time, iterations, &settings, &iterated);
    fs_predict_vehicle_exact(start, time, &settings, &exact);
    printf("%s\n{\"position\":", first ? "" : ",");
    dvec(start->position);
    printf(",\"velocity\":");
    fvec(start->velocity);
    printf(",\"orientation\":");
    fquat(start->orientation);
    printf(",\"angularVelocity\":");
    fvec(start->angular_velocity);
    printf(",\"time\":");
    d(time);
    printf(",\"iterations\":%d,\"frame\":\"%s\"", iterations, frame == FS_FRAME_BODY ? "body" : "world");
    printf(",\"iterative\":{\"position\":");
    dvec(iterated.position);
    printf(",\"velocity\":");
    fvec(iterated.velocity);
    printf(",\"orientation\":");
    fquat(iterated.orientation);
    printf("},\"exact\":{\"position\":");
    dvec(exact.position);
    printf(",\"velocity\":");
    fvec(exact.velocity);
    printf(",\"orientation\":");
    fquat(exact.orientation);
    printf("}}");
}

static void aim(int first, int32_t constraint, float speed, float apex, fs_dvec3 target, fs_vec3 target_velocity) {
    fs_aim_shot shot = fs_aim_shot_default();
    fs_aim_target t = {target, target_velocity, {0.0f, 0.0f, 0.0f}};
    fs_firing_solution solutions[FS_MAX_FIRING_SOLUTIONS];
    size_t count = 0, i;
    static const char* const kConstraints[] = {"speed", "horizontalSpeed", "apexAboveStart", "apexAboveTarget"};
    shot.from.y = 1.5;
    shot.constraint = constraint;
    shot.speed = speed;
    shot.apex_height = apex;
    fs_aim_projectile(&shot, &t, solutions, FS_MAX_FIRING_SOLUTIONS, &count);
    printf("%s\n{\"constraint\":\"%s\",\"speed\":", first ? "" : ",", kConstraints[constraint]);
    d(speed);
    printf(",\"apexHeight\":");
    d(apex);
    printf(",\"from\":");
    dvec(shot.from);
    printf(",\"target\":");
    dvec(target);
    printf(",\"targetVelocity\":");
    fvec(target_velocity);
    printf(",\"solutions\":[");
    for (i = 0; i < count; ++i) {
        printf("%s{\"velocity\":", i ? "," : "");
        fvec(solutions[i].velocity);
        printf(",\"time\":");
        d(solutions[i].time);
        printf(",\"hit\":");
        dvec(solutions[i].hit);
        printf(",\"elevation\":");
        d(solutions[i].elevation);
        printf("}");
    }
    printf("]}");
}

/* One entity extrapolated with each DIS algorithm (the same state, every field used by some). */
static void dead_reckoning(int first, int32_t algorithm, float time) {
    fs_dr_state state = {{12.5, 1.25, -40.0},  {6.0f, 0.5f, 9.0f},
                         {-1.5f, 0.25f, 2.0f}, {0.0f, 0.38268343f, 0.0f, 0.92387953f},
                         {0.1f, 0.8f, -0.3f},  0};
    fs_dr_result r;
    fs_status status;
    state.algorithm = algorithm;
    status = fs_dr_predict(&state, time, &r);
    printf("%s{\"position\":", first ? "" : ",");
    dvec(state.position);
    printf(",\"velocity\":");
    fvec(state.velocity);
    printf(",\"acceleration\":");
    fvec(state.acceleration);
    printf(",\"orientation\":");
    fquat(state.orientation);
    printf(",\"angularVelocity\":");
    fvec(state.angular_velocity);
    printf(",\"algorithm\":%d,\"time\":", (int)algorithm);
    d(time);
    printf(",\"status\":%d", status);
    if (status == FS_STATUS_OK) {
        printf(",\"result\":{\"position\":");
        dvec(r.position);
        printf(",\"velocity\":");
        fvec(r.velocity);
        printf(",\"orientation\":");
        fquat(r.orientation);
        printf("}");
    }
    printf("}");
}

int main(void) {
    fs_plane floor_plane = {{0.0f, 1.0f, 0.0f}, 0.0f, 0.0};
    fs_box wall = {{0.0, 1.5, 10.0}, {5.0f, 1.5f, 0.25f}, {0.0f, 0.130526f, 0.0f, 0.991445f}, 0.0f};
    fs_sphere rock = {{2.0, 0.5, 5.0}, 0.5f, 0.0f};
    fs_triangle ramp = {{-3.0, 0.0, 3.0}, {-1.0, 0.0, 3.0}, {-2.0, 1.0, 6.0}};
    fs_material bouncy = {0.8f, 0.1f};
    fs_world* world = fs_world_create();
    fs_dvec3 hand = {0.0, 1.6, 0.0};
    fs_vec3 throws[] = {{0.0f, 4.0f, 12.0f}, {1.5f, 6.0f, 8.0f}, {-2.0f, 3.0f, 5.0f}, {0.5f, -1.0f, 20.0f}};
    fs_vehicle_state car = {{1.0, 0.0, -2.0}, {3.0f, 0.0f, 10.0f}, {0.0f, 0.2f, 0.0f, 0.98f}, {0.0f, 0.5f, 0.1f}};
    fs_dvec3 target = {30.0, 0.0, 40.0};
    fs_vec3 still = {0.0f, 0.0f, 0.0f}, running = {-3.0f, 0.0f, 1.0f};
    int method, engine, first = 1, complete = 1;
    unsigned k;
    if (world == NULL || fs_world_add_plane(world, &floor_plane, NULL) != FS_STATUS_OK ||
        fs_world_add_box(world, &wall, &bouncy) != FS_STATUS_OK ||
        fs_world_add_sphere(world, &rock, NULL) != FS_STATUS_OK ||
        fs_world_add_triangle(world, &ramp, NULL) != FS_STATUS_OK)
        return 1;
    printf("{\"projectiles\":[");
    for (k = 0; k < sizeof throws / sizeof throws[0]; ++k) {
        for (method = FS_METHOD_EXACT; method <= FS_METHOD_ENGINE; ++method) {
            for (engine = FS_ENGINE_CUSTOM; engine <= (method == FS_METHOD_ENGINE ? FS_ENGINE_BOX2D : 0); ++engine) {
                fs_projectile_settings s = fs_projectile_settings_default();
                s.method = method;
                s.engine = method == FS_METHOD_ENGINE ? engine : FS_ENGINE_JOLT;
                s.friction = 0.3f;
                s.radius = k % 2 ? 0.1f : 0.0f;
                s.max_bounces = k == 3 ? 2u : 0xFFFFFFFFu;
                complete &= projectile(first, hand, throws[k], 4.0f, &s, world);
                first = 0;
            }
        }
    }
    {
        fs_projectile_settings s = fs_projectile_settings_default();
        complete &= projectile(0, hand, throws[0], 2.0f, &s, NULL); /* free flight */
    }
    printf("],\"vehicles\":[");
    vehicle(1, &car, 2.0f, 4, FS_FRAME_BODY);
    vehicle(0, &car, 3.5f, 7, FS_FRAME_WORLD);
    printf("],\"aims\":[");
    aim(1, FS_AIM_SPEED, 25.0f, 0.0f, target, still);
    aim(0, FS_AIM_SPEED, 30.0f, 0.0f, target, running);
    aim(0, FS_AIM_HORIZONTAL_SPEED, 12.0f, 0.0f, target, running);
    aim(0, FS_AIM_APEX_ABOVE_START, 0.0f, 8.0f, target, still);
    aim(0, FS_AIM_APEX_ABOVE_TARGET, 0.0f, 5.0f, target, running);
    printf("],\"deadReckoning\":[");
    for (k = FS_DR_STATIC; k <= FS_DR_FVB; ++k) {
        dead_reckoning(k == FS_DR_STATIC, (int32_t)k, 0.75f);
        dead_reckoning(0, (int32_t)k, 3.1f);
    }
    printf("]}\n");
    fs_world_destroy(world);
    return complete ? 0 : 1;
}
