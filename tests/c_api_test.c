/* The C API (foresight_c.h) from C11, through the shared library foresight_c: every entry point,
 * against closed forms computed here (characters, a vehicle's circle, a projectile's parabola and
 * its first impact), and refusals of bad input with the documented status. Prints nothing on
 * success; prints each failed check and exits with 1 otherwise. */
#include <foresight/foresight_c.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                              \
        }                                                                            \
    } while (0)

#define CHECK_STATUS(call, expected)                                                                           \
    do {                                                                                                       \
        const fs_status got_ = (call);                                                                         \
        if (got_ != (expected)) {                                                                              \
            fprintf(stderr, "%s:%d: %s returned %d (%s), expected %s\n", __FILE__, __LINE__, #call, (int)got_, \
                    fs_status_message(got_), #expected);                                                       \
            ++failures;                                                                                        \
        }                                                                                                      \
    } while (0)

/* |actual - expected| <= tolerance * max(1, |expected|) */
#define CHECK_NEAR(actual, expected, tolerance)                                                                       \
    do {                                                                                                              \
        const double a_ = (double)(actual), e_ = (double)(expected);                                                  \
        if (!(fabs(a_ - e_) <= (tolerance)*fmax(1.0, fabs(e_)))) {                                                    \
            fprintf(stderr, "%s:%d: %s = %.9g, expected %s = %.9g (tolerance %g)\n", __FILE__, __LINE__, #actual, a_, \
                    #expected, e_, (double)(tolerance));                                                              \
            ++failures;                                                                                               \
        }                                                                                                             \
    } while (0)

static const double kTol = 1e-5; /* float results of double computations */
static const double kGravity = 9.81;

static fs_vec3 vec3(float x, float y, float z) {
    fs_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static fs_dvec3 dvec3(double x, double y, double z) {
    fs_dvec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static fs_quat identity(void) {
    fs_quat q;
    q.x = 0.0f;
    q.y = 0.0f;
    q.z = 0.0f;
    q.w = 1.0f;
    return q;
}

/* ---- Version, statuses, defaults ------------------------------------------------------------ */

static void test_version_and_statuses(void) {
    int s;
    CHECK(fs_abi_version() == FS_ABI_VERSION);
    CHECK(strcmp(fs_status_message(FS_STATUS_OK), "ok") == 0);
    CHECK(strcmp(fs_status_message(FS_STATUS_NEGATIVE_TIME), "time must be >= 0") == 0);
    for (s = FS_STATUS_OK; s <= FS_STATUS_OUT_OF_RANGE; ++s) {
        const char* message = fs_status_message(s);
        CHECK(message != NULL && message[0] != '\0' && strcmp(message, "unknown status") != 0);
    }
    for (s = FS_STATUS_BUFFER_TOO_SMALL; s <= FS_STATUS_OUT_OF_MEMORY; ++s) {
        const char* message = fs_status_message(s);
        CHECK(message != NULL && message[0] != '\0' && strcmp(message, "unknown status") != 0);
    }
    CHECK(strcmp(fs_status_message(-1), "unknown status") == 0);
    CHECK(strcmp(fs_status_message(FS_STATUS_OUT_OF_RANGE + 1), "unknown status") == 0);
    CHECK(strcmp(fs_status_message(999), "unknown status") == 0);
    CHECK(strcmp(fs_status_message(FS_STATUS_OUT_OF_MEMORY + 1), "unknown status") == 0);
    CHECK(strcmp(fs_status_message(INT32_MIN), "unknown status") == 0);
    CHECK(strcmp(fs_status_message(INT32_MAX), "unknown status") == 0);
}

static void test_defaults(void) {
    const fs_vehicle_settings vehicle = fs_vehicle_settings_default();
    const fs_projectile_settings projectile = fs_projectile_settings_default();
    CHECK(vehicle.frame == FS_FRAME_BODY);
    CHECK(vehicle.forward.x == 0.0f && vehicle.forward.y == 0.0f && vehicle.forward.z == 1.0f);
    CHECK(projectile.method == FS_METHOD_EXACT);
    CHECK(projectile.gravity.x == 0.0f && projectile.gravity.y == -9.81f && projectile.gravity.z == 0.0f);
    CHECK(projectile.step == 0.02f);
    CHECK(projectile.restitution == 0.5f);
    CHECK(projectile.friction == 0.0f);
    CHECK(projectile.radius == 0.0f);
    CHECK(projectile.max_bounces == UINT32_MAX);
    CHECK(projectile.max_steps == 1048576u);
    CHECK(projectile.max_events == 65536u);
    CHECK(projectile.engine == FS_ENGINE_JOLT);
}

/* ---- Characters ----------------------------------------------------------------------------- */

static void test_characters(void) {
    const fs_vec3 a = vec3(0.5f, -9.81f, 1.0f);
    fs_point_state start, out, untouched;
    const double t = 1.5;
    start.position = dvec3(1.0, 2.0, 3.0);
    start.velocity = vec3(3.0f, 0.5f, 4.0f);
    start.reserved = 0.0f;

    /* p + v t */
    CHECK_STATUS(fs_predict_linear(&start, (float)t, &out), FS_STATUS_OK);
    CHECK_NEAR(out.position.x, 1.0 + 3.0 * t, kTol);
    CHECK_NEAR(out.position.y, 2.0 + 0.5 * t, kTol);
    CHECK_NEAR(out.position.z, 3.0 + 4.0 * t, kTol);
    CHECK(out.velocity.x == 3.0f && out.velocity.y == 0.5f && out.velocity.z == 4.0f);
    CHECK(out.reserved == 0.0f);

    /* p + v t + a t^2 / 2, v + a t */
    CHECK_STATUS(fs_predict_accelerated(&start, a, (float)t, &out), FS_STATUS_OK);
    CHECK_NEAR(out.position.x, 1.0 + 3.0 * t + 0.5 * 0.5 * t * t, kTol);
    CHECK_NEAR(out.position.y, 2.0 + 0.5 * t + 0.5 * (double)-9.81f * t * t, kTol);
    CHECK_NEAR(out.position.z, 3.0 + 4.0 * t + 0.5 * 1.0 * t * t, kTol);
    CHECK_NEAR(out.velocity.x, 3.0 + 0.5 * t, kTol);
    CHECK_NEAR(out.velocity.y, 0.5 + (double)-9.81f * t, kTol);
    CHECK_NEAR(out.velocity.z, 4.0 + 1.0 * t, kTol);

    /* in place (out == start) */
    out = start;
    CHECK_STATUS(fs_predict_linear(&out, 2.0f, &out), FS_STATUS_OK);
    CHECK_NEAR(out.position.z, 3.0 + 8.0, kTol);

    /* refusals: nothing written */
    untouched.position = dvec3(-7.0, -7.0, -7.0);
    untouched.velocity = vec3(-7.0f, -7.0f, -7.0f);
    untouched.reserved = -7.0f;
    out = untouched;
    CHECK_STATUS(fs_predict_linear(NULL, 1.0f, &out), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_linear(&start, 1.0f, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_accelerated(NULL, a, 1.0f, &out), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_accelerated(&start, a, 1.0f, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_linear(&start, -1.0f, &out), FS_STATUS_NEGATIVE_TIME);
    CHECK_STATUS(fs_predict_accelerated(&start, a, -0.5f, &out), FS_STATUS_NEGATIVE_TIME);
    CHECK_STATUS(fs_predict_linear(&start, NAN, &out), FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_predict_accelerated(&start, a, INFINITY, &out), FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_predict_accelerated(&start, vec3(0.0f, NAN, 0.0f), 1.0f, &out), FS_STATUS_NON_FINITE_INPUT);
    {
        fs_point_state bad = start;
        bad.position.y = NAN;
        CHECK_STATUS(fs_predict_linear(&bad, 1.0f, &out), FS_STATUS_NON_FINITE_INPUT);
        bad = start;
        bad.velocity.x = INFINITY;
        CHECK_STATUS(fs_predict_accelerated(&bad, a, 1.0f, &out), FS_STATUS_NON_FINITE_INPUT);
        bad = start;
        /* beyond float's range: infinite in a float build (refused), kept in a double build */
        bad = start;
        bad.position.x = -1e300;
        bad.velocity = vec3(0.0f, 0.0f, 0.0f);
        out = untouched;
        {
            const fs_status s = fs_predict_linear(&bad, 1.0f, &out);
            CHECK(s == FS_STATUS_NON_FINITE_INPUT || (s == FS_STATUS_OK && out.position.x == -1e300));
            if (s != FS_STATUS_OK) CHECK(memcmp(&out, &untouched, sizeof out) == 0);
        }
    }
    {
        fs_point_state huge = start;
        huge.velocity = vec3(3e38f, 0.0f, 0.0f);
        CHECK_STATUS(fs_predict_linear(&huge, 10.0f, &out), FS_STATUS_NON_FINITE_RESULT);
    }
    out = untouched;
    CHECK_STATUS(fs_predict_linear(&start, -1.0f, &out), FS_STATUS_NEGATIVE_TIME);
    CHECK(memcmp(&out, &untouched, sizeof out) == 0);
}

/* ---- Vehicles ------------------------------------------------------------------------------- */

static void test_vehicles(void) {
    /* 10 m/s along +Z, turning at 0.5 rad/s about +Y (body frame): a circle of radius v / w =
     * 20 m about (20, 0, 0); after t the heading is wt, the position R (1 - cos wt, 0, sin wt). */
    const double v = 10.0, w = 0.5, radius = v / w;
    const fs_vehicle_settings settings = fs_vehicle_settings_default();
    fs_vehicle_state car, out, untouched;
    double t;
    car.position = dvec3(0.0, 0.0, 0.0);
    car.velocity = vec3(0.0f, 0.0f, (float)v);
    car.orientation = identity();
    car.angular_velocity = vec3(0.0f, (float)w, 0.0f);

    for (t = 0.0; t <= 12.0; t += 1.5) {
        const double angle = w * t;
        CHECK_STATUS(fs_predict_vehicle_exact(&car, (float)t, &settings, &out), FS_STATUS_OK);
        CHECK_NEAR(out.position.x, radius * (1.0 - cos(angle)), kTol);
        CHECK_NEAR(out.position.y, 0.0, kTol);
        CHECK_NEAR(out.position.z, radius * sin(angle), kTol);
        CHECK_NEAR(hypot(out.position.x - radius, out.position.z), radius, kTol);
        CHECK_NEAR(out.velocity.x, v * sin(angle), kTol);
        CHECK_NEAR(out.velocity.z, v * cos(angle), kTol);
        /* orientation: angle wt about +Y (either sign of the quaternion) */
        CHECK_NEAR(fabs(out.orientation.y), fabs(sin(angle / 2.0)), kTol);
        CHECK_NEAR(fabs(out.orientation.w), fabs(cos(angle / 2.0)), kTol);
        CHECK_NEAR(out.orientation.x, 0.0, kTol);
        CHECK_NEAR(out.orientation.z, 0.0, kTol);
        CHECK_NEAR(out.angular_velocity.y, w, 0.0);
    }

    /* The article's loop converges to the circle as 1/N: 4 steps are metres off after 2 s, 4096
     * steps millimetres. */
    {
        const double angle = w * 2.0;
        const double ex = radius * (1.0 - cos(angle)), ez = radius * sin(angle);
        CHECK_STATUS(fs_predict_vehicle_iterative(&car, 2.0f, 4, &settings, &out), FS_STATUS_OK);
        {
            const double error4 = hypot(out.position.x - ex, out.position.z - ez);
            CHECK(error4 > 0.5 && error4 < 4.0);
        }
        CHECK_STATUS(fs_predict_vehicle_iterative(&car, 2.0f, 4096, &settings, &out), FS_STATUS_OK);
        CHECK(hypot(out.position.x - ex, out.position.z - ez) < 0.01);
        CHECK_NEAR(hypot(out.velocity.x, out.velocity.z), v, kTol);
    }

    /* World frame: the same motion for an upright vehicle turning about world +Y. */
    {
        fs_vehicle_settings world = settings;
        world.frame = FS_FRAME_WORLD;
        CHECK_STATUS(fs_predict_vehicle_exact(&car, 3.0f, &world, &out), FS_STATUS_OK);
        CHECK_NEAR(out.position.x, radius * (1.0 - cos(1.5)), kTol);
        CHECK_NEAR(out.position.z, radius * sin(1.5), kTol);
    }

    /* Refusals: nothing written. */
    untouched = car;
    untouched.position.x = -7.0;
    out = untouched;
    CHECK_STATUS(fs_predict_vehicle_exact(NULL, 1.0f, &settings, &out), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_vehicle_exact(&car, 1.0f, NULL, &out), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_vehicle_exact(&car, 1.0f, &settings, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_vehicle_iterative(NULL, 1.0f, 4, &settings, &out), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_vehicle_iterative(&car, 1.0f, 4, NULL, &out), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_vehicle_iterative(&car, 1.0f, 4, &settings, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_vehicle_exact(&car, -1.0f, &settings, &out), FS_STATUS_NEGATIVE_TIME);
    CHECK_STATUS(fs_predict_vehicle_iterative(&car, -1.0f, 4, &settings, &out), FS_STATUS_NEGATIVE_TIME);
    CHECK_STATUS(fs_predict_vehicle_exact(&car, NAN, &settings, &out), FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_predict_vehicle_iterative(&car, NAN, 4, &settings, &out), FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_predict_vehicle_iterative(&car, 1.0f, 0, &settings, &out), FS_STATUS_INVALID_ITERATIONS);
    CHECK_STATUS(fs_predict_vehicle_iterative(&car, 1.0f, -4, &settings, &out), FS_STATUS_INVALID_ITERATIONS);
    CHECK_STATUS(fs_predict_vehicle_iterative(&car, 1.0f, (1 << 20) + 1, &settings, &out),
                 FS_STATUS_INVALID_ITERATIONS);
    {
        fs_vehicle_settings bad = settings;
        bad.frame = 2;
        CHECK_STATUS(fs_predict_vehicle_exact(&car, 1.0f, &bad, &out), FS_STATUS_INVALID_SETTING);
        CHECK_STATUS(fs_predict_vehicle_iterative(&car, 1.0f, 4, &bad, &out), FS_STATUS_INVALID_SETTING);
        bad.frame = -1;
        CHECK_STATUS(fs_predict_vehicle_exact(&car, 1.0f, &bad, &out), FS_STATUS_INVALID_SETTING);
        bad = settings;
        bad.forward = vec3(0.0f, 0.0f, 0.0f);
        CHECK_STATUS(fs_predict_vehicle_exact(&car, 1.0f, &bad, &out), FS_STATUS_ZERO_VECTOR);
        CHECK_STATUS(fs_predict_vehicle_iterative(&car, 1.0f, 4, &bad, &out), FS_STATUS_ZERO_VECTOR);
        bad.forward = vec3(NAN, 0.0f, 1.0f);
        CHECK_STATUS(fs_predict_vehicle_exact(&car, 1.0f, &bad, &out), FS_STATUS_NON_FINITE_INPUT);
    }
    {
        fs_vehicle_state bad = car;
        bad.orientation.w = 0.0f;
        CHECK_STATUS(fs_predict_vehicle_exact(&bad, 1.0f, &settings, &out), FS_STATUS_ZERO_QUATERNION);
        CHECK_STATUS(fs_predict_vehicle_iterative(&bad, 1.0f, 4, &settings, &out), FS_STATUS_ZERO_QUATERNION);
        bad = car;
        bad.angular_velocity.z = NAN;
        CHECK_STATUS(fs_predict_vehicle_exact(&bad, 1.0f, &settings, &out), FS_STATUS_NON_FINITE_INPUT);
        bad = car;
        bad.position.z = NAN;
        CHECK_STATUS(fs_predict_vehicle_iterative(&bad, 1.0f, 4, &settings, &out), FS_STATUS_NON_FINITE_INPUT);
    }
    CHECK(memcmp(&out, &untouched, sizeof out) == 0);
}

/* ---- Worlds --------------------------------------------------------------------------------- */

static fs_plane floor_plane(void) {
    fs_plane p;
    p.normal = vec3(0.0f, 1.0f, 0.0f);
    p.reserved = 0.0f;
    p.distance = 0.0;
    return p;
}

static void test_world_refusals(void) {
    fs_world* world = fs_world_create();
    const fs_plane good_plane = floor_plane();
    fs_plane plane = good_plane;
    fs_sphere sphere;
    fs_box box;
    fs_triangle triangle;
    fs_material material;
    CHECK(world != NULL);
    if (world == NULL) return;
    sphere.center = dvec3(0.0, 1.0, 0.0);
    sphere.radius = 1.0f;
    sphere.reserved = 0.0f;
    box.center = dvec3(0.0, 0.5, 0.0);
    box.half_extents = vec3(0.5f, 0.5f, 0.5f);
    box.orientation = identity();
    box.rounding = 0.0f;
    triangle.a = dvec3(0.0, 0.0, 0.0);
    triangle.b = dvec3(1.0, 0.0, 0.0);
    triangle.c = dvec3(0.0, 0.0, 1.0);
    material.restitution = 0.3f;
    material.friction = 0.2f;

    CHECK_STATUS(fs_world_add_plane(world, &plane, NULL), FS_STATUS_OK);
    CHECK_STATUS(fs_world_add_plane(world, &plane, &material), FS_STATUS_OK);
    CHECK_STATUS(fs_world_add_sphere(world, &sphere, NULL), FS_STATUS_OK);
    CHECK_STATUS(fs_world_add_box(world, &box, &material), FS_STATUS_OK);
    CHECK_STATUS(fs_world_add_triangle(world, &triangle, NULL), FS_STATUS_OK);

    CHECK_STATUS(fs_world_add_plane(NULL, &plane, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_world_add_plane(world, NULL, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_world_add_sphere(NULL, &sphere, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_world_add_sphere(world, NULL, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_world_add_box(NULL, &box, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_world_add_box(world, NULL, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_world_add_triangle(NULL, &triangle, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_world_add_triangle(world, NULL, NULL), FS_STATUS_NULL_POINTER);

    plane.normal = vec3(0.0f, 0.0f, 0.0f);
    CHECK_STATUS(fs_world_add_plane(world, &plane, NULL), FS_STATUS_ZERO_VECTOR);
    plane = good_plane;
    plane.distance = NAN;
    CHECK_STATUS(fs_world_add_plane(world, &plane, NULL), FS_STATUS_NON_FINITE_INPUT);
    plane = good_plane;
    material.restitution = 2.0f;
    CHECK_STATUS(fs_world_add_plane(world, &plane, &material), FS_STATUS_INVALID_RESTITUTION);
    material.restitution = NAN;
    CHECK_STATUS(fs_world_add_plane(world, &plane, &material), FS_STATUS_NON_FINITE_INPUT);
    material.restitution = -1.0f; /* negative: none */
    material.friction = -1.0f;
    CHECK_STATUS(fs_world_add_plane(world, &plane, &material), FS_STATUS_OK);

    sphere.radius = 0.0f;
    CHECK_STATUS(fs_world_add_sphere(world, &sphere, NULL), FS_STATUS_INVALID_RADIUS);
    sphere.radius = -1.0f;
    CHECK_STATUS(fs_world_add_sphere(world, &sphere, NULL), FS_STATUS_INVALID_RADIUS);
    sphere.radius = 1.0f;
    sphere.center.x = INFINITY;
    CHECK_STATUS(fs_world_add_sphere(world, &sphere, NULL), FS_STATUS_NON_FINITE_INPUT);
    sphere.center.x = 1e300; /* beyond float's range: refused in a float build */
    {
        const fs_status s = fs_world_add_sphere(world, &sphere, NULL);
        CHECK(s == FS_STATUS_NON_FINITE_INPUT || s == FS_STATUS_OK);
    }

    box.half_extents.y = 0.0f;
    CHECK_STATUS(fs_world_add_box(world, &box, NULL), FS_STATUS_DEGENERATE_SHAPE);
    box.half_extents.y = 0.5f;
    box.orientation.w = 0.0f;
    CHECK_STATUS(fs_world_add_box(world, &box, NULL), FS_STATUS_ZERO_QUATERNION);
    box.orientation = identity();
    box.rounding = 0.6f;
    CHECK_STATUS(fs_world_add_box(world, &box, NULL), FS_STATUS_INVALID_RADIUS);
    box.rounding = NAN;
    CHECK_STATUS(fs_world_add_box(world, &box, NULL), FS_STATUS_NON_FINITE_INPUT);

    triangle.c = dvec3(2.0, 0.0, 0.0); /* collinear */
    CHECK_STATUS(fs_world_add_triangle(world, &triangle, NULL), FS_STATUS_DEGENERATE_SHAPE);
    triangle.c = dvec3(0.0, NAN, 1.0);
    CHECK_STATUS(fs_world_add_triangle(world, &triangle, NULL), FS_STATUS_NON_FINITE_INPUT);

    fs_world_destroy(world);
    fs_world_destroy(NULL);

    /* Repeated creation and destruction with shapes (LeakSanitizer checks the ASan build). */
    {
        int i;
        for (i = 0; i < 200; ++i) {
            fs_world* w = fs_world_create();
            CHECK(w != NULL);
            if (w == NULL) return;
            plane = good_plane;
            sphere.center = dvec3(0.0, 1.0, 0.0);
            CHECK_STATUS(fs_world_add_plane(w, &plane, NULL), FS_STATUS_OK);
            if (i % 2 == 0) CHECK_STATUS(fs_world_add_sphere(w, &sphere, NULL), FS_STATUS_OK);
            fs_world_destroy(w);
        }
    }
}

/* ---- Projectiles ---------------------------------------------------------------------------- */

/* The first time y(t) = y0 + vy t - g t^2 / 2 reaches `height` (falling). */
static double impact_time(double y0, double vy, double height) {
    const double a = 0.5 * kGravity, c = height - y0;
    return (vy + sqrt(vy * vy - 4.0 * a * c)) / (2.0 * a);
}

static void test_projectile_free_flight(void) {
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_trajectory_point points[256];
    fs_projectile_result result;
    const double t = 1.2;
    const double px = 1.0, py = 2.0, pz = -3.0, vx = 4.0, vy = 6.0, vz = 1.5;
    int method;
    for (method = FS_METHOD_EXACT; method <= FS_METHOD_STEPPED; ++method) {
        size_t i;
        settings.method = method;
        CHECK_STATUS(fs_predict_projectile(dvec3(px, py, pz), vec3((float)vx, (float)vy, (float)vz), (float)t,
                                           &settings, NULL, points, 256, &result),
                     FS_STATUS_OK);
        CHECK_NEAR(result.time, t, kTol);
        CHECK_NEAR(result.position.x, px + vx * t, kTol);
        CHECK_NEAR(result.position.y, py + vy * t - 0.5 * kGravity * t * t, kTol);
        CHECK_NEAR(result.position.z, pz + vz * t, kTol);
        CHECK_NEAR(result.velocity.y, vy - kGravity * t, kTol);
        CHECK(result.bounces == 0 && result.at_rest == 0 && result.stopped_at_hit == 0);
        CHECK(result.trajectory_size == 61 && result.trajectory_needed == 61); /* Start, 60 steps */
        CHECK(points[0].event == FS_EVENT_START && points[0].time == 0.0f);
        CHECK(points[0].position.x == px && points[0].position.y == py && points[0].position.z == pz);
        CHECK(points[60].event == FS_EVENT_END);
        for (i = 1; i < result.trajectory_size; ++i) {
            const double ti = (double)points[i].time;
            CHECK_NEAR(ti, 0.02 * (double)i, kTol);
            CHECK_NEAR(points[i].position.x, px + vx * ti, kTol);
            CHECK_NEAR(points[i].position.y, py + vy * ti - 0.5 * kGravity * ti * ti, kTol);
            CHECK(points[i].normal.x == 0.0f && points[i].normal.y == 0.0f && points[i].normal.z == 0.0f);
        }
    }
    /* no buffer at all: the result alone */
    settings.method = FS_METHOD_EXACT;
    CHECK_STATUS(fs_predict_projectile(dvec3(px, py, pz), vec3((float)vx, (float)vy, (float)vz), (float)t, &settings,
                                       NULL, NULL, 0, &result),
                 FS_STATUS_OK);
    CHECK(result.trajectory_size == 0 && result.trajectory_needed == 61);
    CHECK_NEAR(result.position.x, px + vx * t, kTol);
}

/* A throw onto the floor y = 0: the first impact at the parabola's root. */
static void test_projectile_floor(void) {
    fs_world* world = fs_world_create();
    const fs_plane plane = floor_plane();
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_trajectory_point points[512];
    fs_projectile_result result;
    const double y0 = 2.0, vx = 3.0, vy = 5.0;
    const double root = impact_time(y0, vy, 0.0);
    size_t i, bounce = 0;
    CHECK(world != NULL);
    if (world == NULL) return;
    CHECK_STATUS(fs_world_add_plane(world, &plane, NULL), FS_STATUS_OK);

    /* Stop at the first impact (max_bounces 0): the result is the impact. */
    settings.max_bounces = 0;
    CHECK_STATUS(fs_predict_projectile(dvec3(0.0, y0, 0.0), vec3((float)vx, (float)vy, 0.0f), 5.0f, &settings, world,
                                       points, 512, &result),
                 FS_STATUS_OK);
    CHECK(result.stopped_at_hit == 1);
    CHECK(result.bounces == 0);
    CHECK_NEAR(result.time, root, kTol);
    CHECK_NEAR(result.position.x, vx * root, kTol);
    CHECK_NEAR(result.position.y, 0.0, kTol);
    CHECK_NEAR(result.velocity.y, vy - kGravity * root, kTol);
    CHECK(result.hit_normal.x == 0.0f && result.hit_normal.y == 1.0f && result.hit_normal.z == 0.0f);
    CHECK(points[result.trajectory_size - 1].event == FS_EVENT_HIT);
    CHECK_NEAR(points[result.trajectory_size - 1].time, root, kTol);

    /* Bouncing on (restitution 0.5): a Bounce point at the root, the vertical speed halved. */
    settings.max_bounces = UINT32_MAX;
    CHECK_STATUS(fs_predict_projectile(dvec3(0.0, y0, 0.0), vec3((float)vx, (float)vy, 0.0f), 2.0f, &settings, world,
                                       points, 512, &result),
                 FS_STATUS_OK);
    CHECK(result.bounces >= 1);
    for (i = 0; i < result.trajectory_size; ++i) {
        if (points[i].event == FS_EVENT_BOUNCE) {
            bounce = i;
            break;
        }
    }
    CHECK(bounce > 0);
    CHECK_NEAR(points[bounce].time, root, kTol);
    CHECK_NEAR(points[bounce].position.x, vx * root, kTol);
    CHECK_NEAR(points[bounce].velocity.y, -0.5 * (vy - kGravity * root), kTol);
    CHECK(points[bounce].normal.y == 1.0f);

    /* The Stepped method (the article's loop) finds the impact within its step. */
    settings.method = FS_METHOD_STEPPED;
    settings.max_bounces = 0;
    CHECK_STATUS(fs_predict_projectile(dvec3(0.0, y0, 0.0), vec3((float)vx, (float)vy, 0.0f), 5.0f, &settings, world,
                                       points, 512, &result),
                 FS_STATUS_OK);
    CHECK(result.stopped_at_hit == 1);
    CHECK(fabs((double)result.time - root) <= 0.02 + kTol);
    CHECK_NEAR(result.position.y, 0.0, 1e-4);

    /* The Engine method (Jolt by default) runs and bounces off the floor; all engines run. */
    settings.method = FS_METHOD_ENGINE;
    settings.max_bounces = UINT32_MAX;
    for (settings.engine = FS_ENGINE_CUSTOM; settings.engine <= FS_ENGINE_BOX2D; ++settings.engine) {
        CHECK_STATUS(fs_predict_projectile(dvec3(0.0, y0, 0.0), vec3((float)vx, (float)vy, 0.0f), 2.0f, &settings,
                                           world, points, 512, &result),
                     FS_STATUS_OK);
        CHECK(result.bounces >= 1);
        CHECK(result.position.y > -0.1);
    }
    fs_world_destroy(world);
}

/* Dropped from y = 5 onto a sphere, a box and a triangle whose tops are at y = 1. */
static void test_projectile_shapes(void) {
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_projectile_result result;
    fs_sphere sphere;
    fs_box box;
    fs_triangle triangle;
    const double expected = impact_time(5.0, 0.0, 1.0);
    int shape;
    settings.max_bounces = 0;
    sphere.center = dvec3(0.0, 0.0, 0.0);
    sphere.radius = 1.0f;
    sphere.reserved = 0.0f;
    box.center = dvec3(0.0, 0.0, 0.0);
    box.half_extents = vec3(2.0f, 1.0f, 2.0f);
    box.orientation = identity();
    box.rounding = 0.0f;
    triangle.a = dvec3(-1.0, 1.0, -1.0);
    triangle.b = dvec3(2.0, 1.0, -1.0);
    triangle.c = dvec3(-1.0, 1.0, 2.0);
    for (shape = 0; shape < 3; ++shape) {
        fs_world* world = fs_world_create();
        CHECK(world != NULL);
        if (world == NULL) return;
        if (shape == 0) CHECK_STATUS(fs_world_add_sphere(world, &sphere, NULL), FS_STATUS_OK);
        if (shape == 1) CHECK_STATUS(fs_world_add_box(world, &box, NULL), FS_STATUS_OK);
        if (shape == 2) CHECK_STATUS(fs_world_add_triangle(world, &triangle, NULL), FS_STATUS_OK);
        CHECK_STATUS(fs_predict_projectile(dvec3(0.0, 5.0, 0.0), vec3(0.0f, 0.0f, 0.0f), 3.0f, &settings, world, NULL,
                                           0, &result),
                     FS_STATUS_OK);
        CHECK(result.stopped_at_hit == 1);
        CHECK_NEAR(result.time, expected, kTol);
        CHECK_NEAR(result.position.y, 1.0, kTol);
        CHECK_NEAR(fabs((double)result.hit_normal.y), 1.0, kTol);
        fs_world_destroy(world);
    }
}

static void test_projectile_buffers_and_refusals(void) {
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_trajectory_point small[3], whole[256];
    fs_projectile_result result, untouched;
    const fs_dvec3 p = dvec3(0.0, 1.0, 0.0);
    const fs_vec3 v = vec3(1.0f, 2.0f, 3.0f);

    /* capacity: steps + 3 + 2 * 64 */
    settings.method = FS_METHOD_STEPPED;
    CHECK(fs_trajectory_capacity(3.0f, &settings) == 150 + 3 + 128);
    settings.method = FS_METHOD_EXACT;
    CHECK(fs_trajectory_capacity(0.0f, &settings) == 3 + 128);
    CHECK(fs_trajectory_capacity(1.0f, NULL) == 0);
    CHECK(fs_trajectory_capacity(-1.0f, &settings) == 0);
    CHECK(fs_trajectory_capacity(NAN, &settings) == 0);
    CHECK(fs_trajectory_capacity(INFINITY, &settings) == 0);
    settings.method = 7;
    CHECK(fs_trajectory_capacity(1.0f, &settings) == 0);
    settings.method = FS_METHOD_EXACT;
    settings.step = 0.0f;
    CHECK(fs_trajectory_capacity(1.0f, &settings) == 0);
    settings = fs_projectile_settings_default();

    /* Too small a buffer: BUFFER_TOO_SMALL, the result and the first points written; a buffer of
     * trajectory_needed points then holds it all, with the same first points. */
    CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &settings, NULL, small, 3, &result), FS_STATUS_BUFFER_TOO_SMALL);
    CHECK(result.trajectory_size == 3 && result.trajectory_needed == 51);
    CHECK_NEAR(result.position.y, 1.0 + 2.0 - 0.5 * kGravity, kTol);
    CHECK(result.trajectory_needed <= 256);
    CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &settings, NULL, whole, (size_t)result.trajectory_needed, &result),
                 FS_STATUS_OK);
    CHECK(result.trajectory_size == 51);
    CHECK(memcmp(small, whole, sizeof small) == 0);
    CHECK(fs_trajectory_capacity(1.0f, &settings) >= 51);

    /* Refusals: `out` untouched. */
    memset(&untouched, 0x5a, sizeof untouched);
    result = untouched;
    CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, NULL, NULL, whole, 256, &result), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &settings, NULL, whole, 256, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &settings, NULL, NULL, 5, &result), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_predict_projectile(p, v, -1.0f, &settings, NULL, whole, 256, &result), FS_STATUS_NEGATIVE_TIME);
    CHECK_STATUS(fs_predict_projectile(p, v, NAN, &settings, NULL, whole, 256, &result), FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_predict_projectile(dvec3(0.0, NAN, 0.0), v, 1.0f, &settings, NULL, whole, 256, &result),
                 FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_predict_projectile(p, vec3(INFINITY, 0.0f, 0.0f), 1.0f, &settings, NULL, whole, 256, &result),
                 FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_predict_projectile(p, vec3(2e6f, 0.0f, 0.0f), 1.0f, &settings, NULL, whole, 256, &result),
                 FS_STATUS_OUT_OF_RANGE);
    {
        const fs_status s =
            fs_predict_projectile(dvec3(1e300, 0.0, 0.0), v, 1.0f, &settings, NULL, whole, 256, &result);
        CHECK(s == FS_STATUS_NON_FINITE_INPUT || s == FS_STATUS_OUT_OF_RANGE);
    }
    CHECK_STATUS(fs_predict_projectile(dvec3(2e8, 0.0, 0.0), v, 1.0f, &settings, NULL, whole, 256, &result),
                 FS_STATUS_OUT_OF_RANGE);
    {
        fs_projectile_settings bad = settings;
        bad.method = 3;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_SETTING);
        bad.method = -1;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_SETTING);
        bad = settings;
        bad.engine = FS_ENGINE_BOX2D + 1;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_SETTING);
        bad.engine = -1;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_SETTING);
        bad = settings;
        bad.step = 0.0f;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_STEP);
        bad.step = NAN;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_STEP);
        bad = settings;
        bad.restitution = 1.5f;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_RESTITUTION);
        bad = settings;
        bad.friction = -0.1f;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_FRICTION);
        bad = settings;
        bad.radius = -0.1f;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_INVALID_RADIUS);
        bad = settings;
        bad.gravity.y = NAN;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_NON_FINITE_INPUT);
        bad = settings;
        bad.max_steps = 10;
        CHECK_STATUS(fs_predict_projectile(p, v, 1.0f, &bad, NULL, whole, 256, &result), FS_STATUS_TOO_MANY_STEPS);
    }
    CHECK(memcmp(&result, &untouched, sizeof result) == 0);
}

/* A sphere resting in a box of planes hits the event cap. */
static void test_projectile_event_cap(void) {
    fs_world* world = fs_world_create();
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_projectile_result result, untouched;
    fs_plane plane = floor_plane();
    CHECK(world != NULL);
    if (world == NULL) return;
    CHECK_STATUS(fs_world_add_plane(world, &plane, NULL), FS_STATUS_OK);
    plane.normal = vec3(0.0f, -1.0f, 0.0f); /* a ceiling at y = 1 */
    plane.distance = -1.0;
    CHECK_STATUS(fs_world_add_plane(world, &plane, NULL), FS_STATUS_OK);
    settings.restitution = 1.0f;
    settings.gravity = vec3(0.0f, 0.0f, 0.0f);
    settings.max_events = 4;
    memset(&untouched, 0x5a, sizeof untouched);
    result = untouched;
    CHECK_STATUS(
        fs_predict_projectile(dvec3(0.0, 0.5, 0.0), vec3(0.0f, 10.0f, 0.0f), 10.0f, &settings, world, NULL, 0, &result),
        FS_STATUS_TOO_MANY_EVENTS);
    CHECK(memcmp(&result, &untouched, sizeof result) == 0);
    fs_world_destroy(world);
}

/* ---- Aim ------------------------------------------------------------------------------------ */

static void test_aim(void) {
    fs_aim_shot shot = fs_aim_shot_default();
    fs_aim_target target;
    fs_firing_solution solutions[FS_MAX_FIRING_SOLUTIONS], untouched[FS_MAX_FIRING_SOLUTIONS];
    size_t count = 99, i;

    CHECK(shot.constraint == FS_AIM_SPEED && shot.speed == 0.0f && shot.apex_height == 0.0f);
    CHECK(shot.gravity.x == 0.0f && shot.gravity.y == -9.81f && shot.gravity.z == 0.0f);
    CHECK(shot.max_time == 60.0f);
    CHECK(shot.from.x == 0.0 && shot.from.y == 0.0 && shot.from.z == 0.0);

    /* A static target 20 m away at 20 m/s under gravity: the low and the high arc,
     * tan(theta) = (s^2 -+ sqrt(s^4 - g^2 x^2)) / (g x), flight time x / (s cos(theta)). */
    shot.speed = 20.0f;
    target.position = dvec3(20.0, 0.0, 0.0);
    target.velocity = vec3(0.0f, 0.0f, 0.0f);
    target.acceleration = vec3(0.0f, 0.0f, 0.0f);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, FS_MAX_FIRING_SOLUTIONS, &count), FS_STATUS_OK);
    CHECK(count == 2);
    if (count == 2) {
        const double s = 20.0, x = 20.0, root = sqrt(s * s * s * s - kGravity * kGravity * x * x);
        const double low = atan((s * s - root) / (kGravity * x)), high = atan((s * s + root) / (kGravity * x));
        CHECK_NEAR(solutions[0].time, x / (s * cos(low)), kTol);
        CHECK_NEAR(solutions[1].time, x / (s * cos(high)), kTol);
        CHECK_NEAR(solutions[0].elevation, low, kTol);
        CHECK_NEAR(solutions[1].elevation, high, kTol);
        CHECK_NEAR(solutions[0].velocity.x, s * cos(low), kTol);
        CHECK_NEAR(solutions[0].velocity.y, s * sin(low), kTol);
        CHECK_NEAR(solutions[1].velocity.y, s * sin(high), kTol);
        CHECK_NEAR(solutions[0].hit.x, 20.0, kTol);
        CHECK(solutions[0].reserved == 0.0f);
    }

    /* No gravity, a target crossing at 3 m/s: |(10, 3t, 0)| = 5t at t = 2.5, velocity (4, 3, 0). */
    shot.gravity = vec3(0.0f, 0.0f, 0.0f);
    shot.speed = 5.0f;
    target.position = dvec3(10.0, 0.0, 0.0);
    target.velocity = vec3(0.0f, 3.0f, 0.0f);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, FS_MAX_FIRING_SOLUTIONS, &count), FS_STATUS_OK);
    CHECK(count == 1);
    CHECK_NEAR(solutions[0].time, 2.5, kTol);
    CHECK_NEAR(solutions[0].velocity.x, 4.0, kTol);
    CHECK_NEAR(solutions[0].velocity.y, 3.0, kTol);
    CHECK_NEAR(solutions[0].hit.y, 7.5, kTol);

    /* No gravity, a target accelerating at 2 m/s^2: |(10, t^2, 0)| = 5t, t^2 = 5 or 20. */
    target.velocity = vec3(0.0f, 0.0f, 0.0f);
    target.acceleration = vec3(0.0f, 2.0f, 0.0f);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, FS_MAX_FIRING_SOLUTIONS, &count), FS_STATUS_OK);
    CHECK(count == 2);
    CHECK_NEAR(solutions[0].time, sqrt(5.0), kTol);
    CHECK_NEAR(solutions[1].time, sqrt(20.0), kTol);
    CHECK_NEAR(solutions[1].hit.y, 20.0, kTol);
    /* a shorter buffer gets the earliest; none at all only counts nothing */
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 1, &count), FS_STATUS_OK);
    CHECK(count == 1);
    CHECK_NEAR(solutions[0].time, sqrt(5.0), kTol);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, NULL, 0, &count), FS_STATUS_OK);
    CHECK(count == 0);

    /* Out of reach: no solutions, not an error. */
    shot = fs_aim_shot_default();
    shot.speed = 5.0f;
    target.position = dvec3(100.0, 0.0, 0.0);
    target.acceleration = vec3(0.0f, 0.0f, 0.0f);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, FS_MAX_FIRING_SOLUTIONS, &count), FS_STATUS_OK);
    CHECK(count == 0);

    /* The apex constraints: a lob whose apex is 5 m above the start, onto a target on the
     * ground 10 m away: up for sqrt(2 h / g), down as long. */
    shot.constraint = FS_AIM_APEX_ABOVE_START;
    shot.apex_height = 5.0f;
    target.position = dvec3(10.0, 0.0, 0.0);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, FS_MAX_FIRING_SOLUTIONS, &count), FS_STATUS_OK);
    CHECK(count == 1);
    CHECK_NEAR(solutions[0].time, 2.0 * sqrt(2.0 * 5.0 / kGravity), kTol);
    CHECK_NEAR(solutions[0].velocity.y, sqrt(2.0 * kGravity * 5.0), kTol);
    shot.constraint = FS_AIM_APEX_ABOVE_TARGET;
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, FS_MAX_FIRING_SOLUTIONS, &count), FS_STATUS_OK);
    CHECK(count == 1);
    CHECK_NEAR(solutions[0].time, 2.0 * sqrt(2.0 * 5.0 / kGravity), kTol);
    shot.constraint = FS_AIM_HORIZONTAL_SPEED;
    shot.speed = 5.0f;
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, FS_MAX_FIRING_SOLUTIONS, &count), FS_STATUS_OK);
    CHECK(count == 1);
    CHECK_NEAR(solutions[0].time, 2.0, kTol);
    CHECK_NEAR(solutions[0].velocity.x, 5.0, kTol);
    CHECK_NEAR(solutions[0].velocity.y, 0.5 * kGravity * 2.0, kTol);

    /* Refusals: nothing written. */
    shot = fs_aim_shot_default();
    shot.speed = 20.0f;
    memset(untouched, 0x5a, sizeof untouched);
    memcpy(solutions, untouched, sizeof solutions);
    count = 99;
    CHECK_STATUS(fs_aim_projectile(NULL, &target, solutions, 4, &count), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_aim_projectile(&shot, NULL, solutions, 4, &count), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 4, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, NULL, 4, &count), FS_STATUS_NULL_POINTER);
    shot.constraint = 4;
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 4, &count), FS_STATUS_INVALID_SETTING);
    shot.constraint = -1;
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 4, &count), FS_STATUS_INVALID_SETTING);
    shot.constraint = FS_AIM_SPEED;
    shot.max_time = -1.0f;
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 4, &count), FS_STATUS_NEGATIVE_TIME);
    shot.max_time = NAN;
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 4, &count), FS_STATUS_NON_FINITE_INPUT);
    shot.max_time = 60.0f;
    shot.speed = INFINITY;
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 4, &count), FS_STATUS_NON_FINITE_INPUT);
    shot.speed = 20.0f;
    target.velocity.z = NAN;
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 4, &count), FS_STATUS_NON_FINITE_INPUT);
    target.velocity.z = 0.0f;
    shot.constraint = FS_AIM_APEX_ABOVE_START;
    shot.gravity = vec3(0.0f, 0.0f, 0.0f);
    CHECK_STATUS(fs_aim_projectile(&shot, &target, solutions, 4, &count), FS_STATUS_ZERO_VECTOR);
    CHECK(count == 99);
    CHECK(memcmp(solutions, untouched, sizeof solutions) == 0);
    for (i = 0; i < FS_MAX_FIRING_SOLUTIONS; ++i) CHECK(solutions[i].time == untouched[i].time);
}

/* ---- Dead reckoning ------------------------------------------------------------------------- */

static fs_dr_state dr_state(int32_t algorithm) {
    fs_dr_state s;
    memset(&s, 0, sizeof s);
    s.position = dvec3(1.0, 2.0, 3.0);
    s.velocity = vec3(4.0f, 0.0f, -2.0f);
    s.acceleration = vec3(0.0f, -2.0f, 1.0f);
    s.orientation = identity();
    s.angular_velocity = vec3(0.0f, 0.0f, 0.0f);
    s.algorithm = algorithm;
    return s;
}

static void test_dead_reckoning(void) {
    fs_dr_state s = dr_state(FS_DR_FPW);
    fs_dr_result r, untouched;
    fs_dr_state states[3];
    double timestamps[3];
    fs_dr_result results[3];
    size_t refused = 99;
    const double t = 0.5;

    CHECK(strcmp(fs_dr_algorithm_name(FS_DR_STATIC), "STATIC") == 0);
    CHECK(strcmp(fs_dr_algorithm_name(FS_DR_RVB), "RVB") == 0);
    CHECK(strcmp(fs_dr_algorithm_name(0), "?") == 0 && strcmp(fs_dr_algorithm_name(257), "?") == 0);

    /* FPW: p + v t. */
    CHECK_STATUS(fs_dr_predict(&s, (float)t, &r), FS_STATUS_OK);
    CHECK_NEAR(r.position.x, 1.0 + 4.0 * t, kTol);
    CHECK_NEAR(r.position.y, 2.0, kTol);
    CHECK_NEAR(r.position.z, 3.0 - 2.0 * t, kTol);
    CHECK(r.velocity.x == 4.0f && r.velocity.z == -2.0f && r.orientation.w == 1.0f && r.reserved == 0.0f);

    /* FVW: p + v t + a t^2 / 2, velocity v + a t. */
    s.algorithm = FS_DR_FVW;
    CHECK_STATUS(fs_dr_predict(&s, (float)t, &r), FS_STATUS_OK);
    CHECK_NEAR(r.position.y, 2.0 - 2.0 * t * t / 2.0, kTol);
    CHECK_NEAR(r.position.z, 3.0 - 2.0 * t + t * t / 2.0, kTol);
    CHECK_NEAR(r.velocity.y, -2.0 * t, kTol);

    /* RPB: a body velocity (0, 0, v) turning at w about +Y traces a circle of radius v / w:
     * after t, position p + (r (1 - cos wt), 0, r sin wt) and the yaw wt. */
    s = dr_state(FS_DR_RPB);
    s.velocity = vec3(0.0f, 0.0f, 10.0f);
    s.angular_velocity = vec3(0.0f, 0.5f, 0.0f);
    CHECK_STATUS(fs_dr_predict(&s, 2.0f, &r), FS_STATUS_OK);
    CHECK_NEAR(r.position.x, 1.0 + 20.0 * (1.0 - cos(1.0)), kTol);
    CHECK_NEAR(r.position.y, 2.0, kTol);
    CHECK_NEAR(r.position.z, 3.0 + 20.0 * sin(1.0), kTol);
    CHECK_NEAR(r.orientation.y, sin(0.5), kTol);
    CHECK_NEAR(r.orientation.w, cos(0.5), kTol);
    CHECK_NEAR(r.velocity.z, 10.0, kTol); /* body axes: unchanged */

    /* Refusals: out untouched. */
    memset(&untouched, 0x5a, sizeof untouched);
    r = untouched;
    s = dr_state(FS_DR_FPW);
    CHECK_STATUS(fs_dr_predict(NULL, 1.0f, &r), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_dr_predict(&s, 1.0f, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_dr_predict(&s, -1.0f, &r), FS_STATUS_NEGATIVE_TIME);
    CHECK_STATUS(fs_dr_predict(&s, NAN, &r), FS_STATUS_NON_FINITE_INPUT);
    s.algorithm = 0;
    CHECK_STATUS(fs_dr_predict(&s, 1.0f, &r), FS_STATUS_INVALID_ALGORITHM);
    s.algorithm = 257; /* would wrap to 1 in a uint8_t */
    CHECK_STATUS(fs_dr_predict(&s, 1.0f, &r), FS_STATUS_INVALID_ALGORITHM);
    s = dr_state(FS_DR_FPW);
    s.velocity.y = NAN;
    CHECK_STATUS(fs_dr_predict(&s, 1.0f, &r), FS_STATUS_NON_FINITE_INPUT);
    s = dr_state(FS_DR_FPW);
    s.orientation.w = 0.0f;
    CHECK_STATUS(fs_dr_predict(&s, 1.0f, &r), FS_STATUS_ZERO_QUATERNION);
    CHECK(memcmp(&r, &untouched, sizeof r) == 0);

    /* Batch: ages time - timestamp, clamped at 0; a refused entity keeps its state. */
    states[0] = dr_state(FS_DR_FPW);
    states[1] = dr_state(FS_DR_FPW);
    states[2] = dr_state(FS_DR_FPW);
    states[2].orientation.w = 0.0f;
    timestamps[0] = 10.0;
    timestamps[1] = 11.0; /* stamped after `time`: age 0 */
    timestamps[2] = 10.0;
    CHECK_STATUS(fs_dr_predict_batch(states, timestamps, 3, 10.5, results, &refused), FS_STATUS_OK);
    CHECK(refused == 1);
    CHECK_NEAR(results[0].position.x, 1.0 + 4.0 * 0.5, kTol);
    CHECK(results[1].position.x == 1.0 && results[1].position.z == 3.0);
    CHECK(results[2].position.x == 1.0 && results[2].velocity.x == 4.0f);
    CHECK_STATUS(fs_dr_predict_batch(NULL, NULL, 0, 0.0, NULL, NULL), FS_STATUS_OK);
    CHECK_STATUS(fs_dr_predict_batch(states, NULL, 3, 0.0, results, NULL), FS_STATUS_NULL_POINTER);
}

static void test_dead_reckoning_receiver(void) {
    fs_dr_receiver_settings settings = fs_dr_receiver_settings_default();
    fs_dr_receiver* receiver = NULL;
    fs_dr_receiver_counters counters;
    fs_dr_state s = dr_state(FS_DR_FPW);
    fs_dr_pose pose;
    int32_t outcome = -1;

    CHECK(settings.mode == FS_DR_MODE_EXTRAPOLATE && settings.smoothing == FS_DR_SMOOTH_PROJECTIVE_VELOCITY);
    CHECK(settings.blend_time == 0.2f && settings.decay_half_life == 0.1f && settings.teleport_distance == 10.0f);
    CHECK(settings.extrapolation_limit == 0.25f && settings.interpolation_delay == 0.1f);
    CHECK(settings.max_future_skew == 1.0f && settings.restart_after == 10.0f);

    settings.mode = 2;
    CHECK_STATUS(fs_dr_receiver_create(&settings, &receiver), FS_STATUS_INVALID_SETTING);
    settings = fs_dr_receiver_settings_default();
    settings.smoothing = -1;
    CHECK_STATUS(fs_dr_receiver_create(&settings, &receiver), FS_STATUS_INVALID_SETTING);
    settings = fs_dr_receiver_settings_default();
    settings.blend_time = 0.0f;
    CHECK_STATUS(fs_dr_receiver_create(&settings, &receiver), FS_STATUS_INVALID_SETTING);
    CHECK(receiver == NULL);
    CHECK_STATUS(fs_dr_receiver_create(NULL, &receiver), FS_STATUS_NULL_POINTER);

    settings = fs_dr_receiver_settings_default();
    settings.smoothing = FS_DR_SMOOTH_SNAP;
    CHECK_STATUS(fs_dr_receiver_create(&settings, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_dr_receiver_create(&settings, &receiver), FS_STATUS_OK);
    CHECK(receiver != NULL);
    if (receiver == NULL) return;

    CHECK_STATUS(fs_dr_receiver_sample(receiver, 0.0, &pose), FS_STATUS_NO_UPDATE);
    /* The first update snaps; sampling 0.2 s after its timestamp shows p + v 0.2. */
    CHECK_STATUS(fs_dr_receiver_receive(receiver, 1.0, &s, 1.05, &outcome), FS_STATUS_OK);
    CHECK(outcome == FS_DR_SNAPPED);
    CHECK_STATUS(fs_dr_receiver_sample(receiver, 1.2, &pose), FS_STATUS_OK);
    CHECK_NEAR(pose.position.x, 1.0 + 4.0 * 0.2, kTol);
    CHECK_NEAR(pose.position.z, 3.0 - 2.0 * 0.2, kTol);
    CHECK(pose.held == 0 && pose.velocity.x == 4.0f);
    /* Past extrapolation_limit (0.25 s) the pose holds at p + v 0.25. */
    CHECK_STATUS(fs_dr_receiver_sample(receiver, 2.0, &pose), FS_STATUS_OK);
    CHECK_NEAR(pose.position.x, 1.0 + 4.0 * 0.25, kTol);
    CHECK(pose.held == 1);
    CHECK_STATUS(fs_dr_receiver_sample(receiver, NAN, &pose), FS_STATUS_NON_FINITE_INPUT);

    /* A duplicate, an older one, an invalid one: dropped and counted. */
    CHECK_STATUS(fs_dr_receiver_receive(receiver, 1.0, &s, 1.1, &outcome), FS_STATUS_OK);
    CHECK(outcome == FS_DR_DUPLICATE);
    CHECK_STATUS(fs_dr_receiver_receive(receiver, 0.5, &s, 1.1, &outcome), FS_STATUS_OK);
    CHECK(outcome == FS_DR_OUT_OF_ORDER);
    s.algorithm = 99;
    CHECK_STATUS(fs_dr_receiver_receive(receiver, 1.5, &s, 1.5, &outcome), FS_STATUS_OK);
    CHECK(outcome == FS_DR_INVALID);
    CHECK_STATUS(fs_dr_receiver_receive(receiver, 1.5, &s, 1.5, NULL), FS_STATUS_OK);
    CHECK_STATUS(fs_dr_receiver_receive(receiver, 1.5, NULL, 1.5, &outcome), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_dr_receiver_receive(NULL, 1.5, &s, 1.5, &outcome), FS_STATUS_NULL_POINTER);

    CHECK_STATUS(fs_dr_receiver_get_counters(receiver, &counters), FS_STATUS_OK);
    CHECK(counters.accepted == 1 && counters.snaps == 1 && counters.duplicates == 1);
    CHECK(counters.out_of_order == 1 && counters.invalid == 2 && counters.held == 1);
    CHECK_STATUS(fs_dr_receiver_get_counters(NULL, &counters), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_dr_receiver_get_counters(receiver, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_dr_receiver_sample(NULL, 1.0, &pose), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_dr_receiver_sample(receiver, 1.0, NULL), FS_STATUS_NULL_POINTER);

    fs_dr_receiver_reset(receiver);
    fs_dr_receiver_reset(NULL);
    CHECK_STATUS(fs_dr_receiver_get_counters(receiver, &counters), FS_STATUS_OK);
    CHECK(counters.accepted == 0 && counters.invalid == 0);
    CHECK_STATUS(fs_dr_receiver_sample(receiver, 1.0, &pose), FS_STATUS_NO_UPDATE);
    fs_dr_receiver_destroy(receiver);
    fs_dr_receiver_destroy(NULL);
}

int main(void) {
    test_version_and_statuses();
    test_defaults();
    test_characters();
    test_vehicles();
    test_world_refusals();
    test_projectile_free_flight();
    test_projectile_floor();
    test_projectile_shapes();
    test_projectile_buffers_and_refusals();
    test_projectile_event_cap();
    test_aim();
    test_dead_reckoning();
    test_dead_reckoning_receiver();
    if (failures != 0) {
        fprintf(stderr, "c_api_test: %d check(s) failed\n", failures);
        return 1;
    }
    return 0;
}
