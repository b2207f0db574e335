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
    for (s = FS_STATUS_BUFFER_TOO_SMALL; s <= FS_STATUS_BACKEND_FAILED; ++s) {
        const char* message = fs_status_message(s);
        CHECK(message != NULL && message[0] != '\0' && strcmp(message, "unknown status") != 0);
    }
    CHECK(strcmp(fs_status_message(-1), "unknown status") == 0);
    CHECK(strcmp(fs_status_message(FS_STATUS_OUT_OF_RANGE + 1), "unknown status") == 0);
    CHECK(strcmp(fs_status_message(999), "unknown status") == 0);
    CHECK(strcmp(fs_status_message(FS_STATUS_BACKEND_FAILED + 1), "unknown status") == 0);
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

/* ---- Callback worlds ------------------------------------------------------------------------ */

/* What a callback does to its hits, to test the library's checks. */
enum {
    kHitGood,
    kHitLongNormal,
    kHitNanFraction,
    kHitFractionAbove1,
    kHitZeroNormal,
    kHitNanPosition,
    kHitRestitution2
};

typedef struct floor_context {
    int calls;
    int mode; /* kHit* */
} floor_context;

/* A game's own cast: the floor y = 0, for a point or a swept sphere. */
static int32_t cast_floor(void* context, const fs_segment_cast* cast, fs_cast_hit* hit) {
    floor_context* floor_ctx = (floor_context*)context;
    const double start = cast->origin.y - cast->radius; /* the sphere's lowest point */
    const double dy = cast->displacement.y;
    double fraction;
    ++floor_ctx->calls;
    if (dy >= 0.0 || start < -1e-4) return 0; /* moving up, or already below */
    fraction = start <= 0.0 ? 0.0 : start / -dy;
    if (fraction > 1.0) return 0;
    hit->fraction = (float)fraction;
    hit->position.x = cast->origin.x + fraction * cast->displacement.x;
    hit->position.y = cast->origin.y + fraction * cast->displacement.y;
    hit->position.z = cast->origin.z + fraction * cast->displacement.z;
    hit->normal = vec3(0.0f, 1.0f, 0.0f);
    switch (floor_ctx->mode) {
        case kHitLongNormal:
            hit->normal = vec3(0.0f, 3.0f, 0.0f);
            break; /* normalised by the library */
        case kHitNanFraction:
            hit->fraction = NAN;
            break;
        case kHitFractionAbove1:
            hit->fraction = 1.5f;
            break;
        case kHitZeroNormal:
            hit->normal = vec3(0.0f, 0.0f, 0.0f);
            break;
        case kHitNanPosition:
            hit->position.y = NAN;
            break;
        case kHitRestitution2:
            hit->restitution = 2.0f;
            break;
        default:
            break;
    }
    return 1;
}

static void test_callback_world(void) {
    floor_context floor_ctx = {0, kHitGood};
    fs_world* world = fs_world_create_callback(cast_floor, &floor_ctx);
    const fs_plane plane = floor_plane();
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_trajectory_point points[512];
    fs_projectile_result result, first;
    const double y0 = 2.0, vx = 3.0, vy = 5.0;
    const double root = impact_time(y0, vy, 0.0);
    int mode;
    CHECK(fs_world_create_callback(NULL, &floor_ctx) == NULL);
    CHECK(world != NULL);
    if (world == NULL) return;
    /* It holds no shapes. */
    CHECK_STATUS(fs_world_add_plane(world, &plane, NULL), FS_STATUS_INVALID_SETTING);

    /* The first impact, where the parabola meets y = 0, found through the caller's cast. */
    settings.max_bounces = 0;
    CHECK_STATUS(fs_predict_projectile(dvec3(0.0, y0, 0.0), vec3((float)vx, (float)vy, 0.0f), 5.0f, &settings, world,
                                       points, 512, &result),
                 FS_STATUS_OK);
    CHECK(floor_ctx.calls > 0);
    CHECK(result.stopped_at_hit == 1);
    CHECK_NEAR(result.time, root, kTol);
    CHECK_NEAR(result.position.x, vx * root, kTol);
    CHECK_NEAR(result.position.y, 0.0, kTol);
    CHECK(result.hit_normal.y == 1.0f);

    /* Bouncing with a 5 cm sphere, every method; a normal of length 3 means the same surface. */
    settings.max_bounces = UINT32_MAX;
    settings.radius = 0.05f;
    for (settings.method = FS_METHOD_EXACT; settings.method <= FS_METHOD_ENGINE; ++settings.method) {
        floor_ctx.mode = kHitGood;
        CHECK_STATUS(fs_predict_projectile(dvec3(0.0, y0, 0.0), vec3((float)vx, (float)vy, 0.0f), 2.0f, &settings,
                                           world, points, 512, &first),
                     FS_STATUS_OK);
        CHECK(first.bounces >= 1);
        CHECK(first.position.y >= 0.05 - 1e-3); /* the sphere stays on the floor */
        floor_ctx.mode = kHitLongNormal;
        CHECK_STATUS(fs_predict_projectile(dvec3(0.0, y0, 0.0), vec3((float)vx, (float)vy, 0.0f), 2.0f, &settings,
                                           world, points, 512, &result),
                     FS_STATUS_OK);
        CHECK(result.position.x == first.position.x && result.position.y == first.position.y);
        CHECK(result.bounces == first.bounces);
    }

    /* Invalid hits end the prediction with INVALID_CALLBACK_HIT and leave the result alone. */
    settings.method = FS_METHOD_EXACT;
    for (mode = kHitNanFraction; mode <= kHitRestitution2; ++mode) {
        floor_ctx.mode = mode;
        result.bounces = 12345u;
        CHECK_STATUS(fs_predict_projectile(dvec3(0.0, y0, 0.0), vec3((float)vx, (float)vy, 0.0f), 2.0f, &settings,
                                           world, points, 512, &result),
                     FS_STATUS_INVALID_CALLBACK_HIT);
        CHECK(result.bounces == 12345u);
    }
    CHECK(strlen(fs_status_message(FS_STATUS_INVALID_CALLBACK_HIT)) > 10);
    fs_world_destroy(world);
}

/* ---- Meshes and Embree worlds ------------------------------------------------------------------ */

/* A floor y = 0 as a 40 m square of two triangles (the second one repeated degenerate). */
static const fs_dvec3 kFloorVertices[4] = {
    {-20.0, 0.0, -20.0}, {20.0, 0.0, -20.0}, {20.0, 0.0, 20.0}, {-20.0, 0.0, 20.0}};
static const uint32_t kFloorIndices[9] = {0, 2, 1, 0, 3, 2, 1, 1, 2};

/* Dropped from y = 5 with (1, 0, 0) m/s and stopped at the first impact: at t = sqrt(10 / g). */
static void check_floor_drop(const fs_world* world) {
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_trajectory_point points[512];
    fs_projectile_result result;
    const double root = sqrt(2.0 * 5.0 / kGravity);
    settings.max_bounces = 0;
    CHECK_STATUS(fs_predict_projectile(dvec3(0.5, 5.0, 0.5), vec3(1.0f, 0.0f, 0.0f), 3.0f, &settings, world, points,
                                       512, &result),
                 FS_STATUS_OK);
    CHECK(result.stopped_at_hit == 1);
    CHECK_NEAR(result.time, root, kTol);
    CHECK_NEAR(result.position.x, 0.5 + root, kTol);
    CHECK_NEAR(result.position.y, 0.0, kTol);
    CHECK(result.hit_normal.y == 1.0f);
}

static void test_meshes(void) {
    fs_world* world = fs_world_create();
    fs_world* embree = fs_world_create_embree();
    fs_mesh_report report = {99, 99, 99};
    const fs_dvec3 bad_vertex[3] = {{0.0, 0.0, 0.0}, {1.0, NAN, 0.0}, {0.0, 0.0, 1.0}};
    const uint32_t out_of_range[3] = {0, 1, 7};
    char error[256];
    FILE* file;
    CHECK(world != NULL);
    if (world == NULL) return;

    /* A static world: the triangles tested one by one. */
    CHECK_STATUS(fs_world_add_mesh(world, kFloorVertices, 4, kFloorIndices, 9, &report), FS_STATUS_OK);
    CHECK(report.triangles == 2 && report.degenerate_triangles == 1 && report.first_degenerate_triangle == 2);
    CHECK_STATUS(fs_world_commit(world, NULL, 0), FS_STATUS_OK); /* nothing to build */
    check_floor_drop(world);
    /* Refused whole. */
    CHECK_STATUS(fs_world_add_mesh(world, bad_vertex, 3, kFloorIndices, 3, NULL), FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_world_add_mesh(world, kFloorVertices, 4, out_of_range, 3, NULL), FS_STATUS_DEGENERATE_SHAPE);
    CHECK_STATUS(fs_world_add_mesh(world, kFloorVertices, 4, kFloorIndices, 8, NULL), FS_STATUS_DEGENERATE_SHAPE);
    CHECK_STATUS(fs_world_add_mesh(world, kFloorVertices, 4, kFloorIndices + 6, 3, NULL), FS_STATUS_DEGENERATE_SHAPE);
    CHECK_STATUS(fs_world_add_mesh(world, NULL, 4, kFloorIndices, 9, NULL), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_world_load_mesh(world, "level.obj", NULL, NULL, 0), FS_STATUS_INVALID_SETTING);
    fs_world_destroy(world);

    if (!fs_embree_available()) {
        CHECK(embree == NULL);
        return;
    }
    CHECK(embree != NULL);
    if (embree == NULL) return;
    /* The same floor in an Embree BVH. */
    CHECK_STATUS(fs_world_add_mesh(embree, kFloorVertices, 4, kFloorIndices, 9, &report), FS_STATUS_OK);
    CHECK(report.triangles == 2 && report.degenerate_triangles == 1 && report.first_degenerate_triangle == 2);
    CHECK_STATUS(fs_world_commit(embree, error, sizeof error), FS_STATUS_OK);
    check_floor_drop(embree);
    fs_world_destroy(embree);

    /* The floor from an OBJ file (written beside the test), and files that are refused. */
    file = fopen("c_api_test_floor.obj", "w");
    CHECK(file != NULL);
    if (file == NULL) return;
    fputs("v -20 0 -20\nv 20 0 -20\nv 20 0 20\nv -20 0 20\nf 1 3 2\nf 1 4 3\n", file);
    fclose(file);
    file = fopen("c_api_test_broken.obj", "w");
    CHECK(file != NULL);
    if (file == NULL) return;
    fputs("v -20 0 -20\nv 20 zero -20\nv 20 0 20\nf 1 3 2\n", file);
    fclose(file);
    embree = fs_world_create_embree();
    CHECK(embree != NULL);
    if (embree == NULL) return;
    CHECK_STATUS(fs_world_load_mesh(embree, "c_api_test_floor.OBJ", &report, error, sizeof error),
                 FS_STATUS_BACKEND_FAILED); /* no such file (the extension's case does not matter) */
    CHECK(strstr(error, "c_api_test_floor.OBJ") != NULL);
    CHECK_STATUS(fs_world_load_mesh(embree, "c_api_test_broken.obj", &report, error, sizeof error),
                 FS_STATUS_BACKEND_FAILED);
    CHECK(strstr(error, "c_api_test_broken.obj") != NULL);
    CHECK_STATUS(fs_world_load_mesh(embree, "c_api_test_broken.obj", &report, error, 8), FS_STATUS_BACKEND_FAILED);
    CHECK(strlen(error) == 7); /* cut to the buffer */
    CHECK_STATUS(fs_world_load_mesh(embree, "c_api_test_floor.stl", &report, error, sizeof error),
                 FS_STATUS_INVALID_SETTING);
    CHECK_STATUS(fs_world_load_mesh(embree, "c_api_test_floor.obj", &report, error, sizeof error), FS_STATUS_OK);
    CHECK(report.triangles == 2 && report.degenerate_triangles == 0);
    CHECK_STATUS(fs_world_commit(embree, error, sizeof error), FS_STATUS_OK);
    check_floor_drop(embree);
    fs_world_destroy(embree);
    remove("c_api_test_floor.obj");
    remove("c_api_test_broken.obj");
}

/* ---- Engine profiles and what a game draws between steps --------------------------------------- */

static void test_engine_profiles(void) {
    fs_engine_profile profile = fs_engine_profile_default(FS_ENGINE_JOLT);
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_trajectory_point points[512], same_points[512];
    fs_projectile_result result, same;
    fs_dvec3 drawn;
    double px = 0.0, py = 2.0, vx = 4.0, vy = 3.0, d;
    int k;
    /* The named defaults (docs/engines.md): Jolt bounces above 1 m/s, PhysX above 2 m/s, Rapier
     * takes 4 sub-steps, Bullet damps before gravity with the power law. */
    CHECK(profile.engine == FS_ENGINE_JOLT && fabs(profile.timestep - 1.0 / 60.0) < 1e-9);
    CHECK(profile.restitution_threshold == 1.0f && profile.order == FS_DAMPING_ORDER_GRAVITY_THEN_DAMPING);
    CHECK(fs_engine_profile_default(FS_ENGINE_PHYSX).restitution_threshold == 2.0f);
    CHECK(fs_engine_profile_default(FS_ENGINE_RAPIER).substeps == 4u);
    CHECK(fs_engine_profile_default(FS_ENGINE_BULLET).damping == FS_DAMPING_LAW_POWER);
    CHECK(fs_engine_profile_default(FS_ENGINE_BULLET).order == FS_DAMPING_ORDER_DAMPING_THEN_GRAVITY);
    CHECK(fs_engine_profile_default(99).engine == FS_ENGINE_CUSTOM);
    /* ammo.js's Bullet 2.83: no bounce threshold, friction warm-started, erp2 0.8. */
    CHECK(fs_engine_profile_ammo_js().engine == FS_ENGINE_BULLET);
    CHECK(fs_engine_profile_ammo_js().restitution_threshold == 0.0f);
    CHECK(fs_engine_profile_ammo_js().friction_warm_start == 0.85f);
    CHECK(fs_engine_profile_ammo_js().split_impulse_correction == 0.8f);
    CHECK_STATUS(fs_validate_engine_profile(&profile), FS_STATUS_OK);

    /* The named profile through either door: the same flight, bit for bit. */
    settings.method = FS_METHOD_ENGINE;
    settings.engine = FS_ENGINE_JOLT;
    CHECK_STATUS(fs_predict_projectile(dvec3(0.0, 2.0, 0.0), vec3(4.0f, 3.0f, 0.0f), 1.0f, &settings, NULL, same_points,
                                       512, &same),
                 FS_STATUS_OK);
    settings.engine = FS_ENGINE_BOX2D; /* ignored: the profile rules */
    CHECK_STATUS(fs_predict_projectile_with_profile(dvec3(0.0, 2.0, 0.0), vec3(4.0f, 3.0f, 0.0f), 1.0f, &settings,
                                                    &profile, NULL, points, 512, &result),
                 FS_STATUS_OK);
    CHECK(result.position.x == same.position.x && result.position.y == same.position.y);
    CHECK(result.trajectory_size == same.trajectory_size);

    /* A game's own settings: 100 Hz and a drag of 0.5 per second (Unity's Rigidbody.drag) on a
     * custom profile, against its recurrence stepped here: v = (v + g dt) max(0, 1 - c dt),
     * p += v dt. */
    profile = fs_engine_profile_default(FS_ENGINE_CUSTOM);
    profile.timestep = 0.01f;
    profile.damping = FS_DAMPING_LAW_LINEAR_CLAMPED;
    profile.linear_damping = 0.5f;
    CHECK(fs_trajectory_capacity_with_profile(1.0f, &settings, &profile) == 100 + 3 + 128);
    CHECK_STATUS(fs_predict_projectile_with_profile(dvec3(0.0, 2.0, 0.0), vec3(4.0f, 3.0f, 0.0f), 1.0f, &settings,
                                                    &profile, NULL, points, 512, &result),
                 FS_STATUS_OK);
    d = 1.0 - 0.5 * (double)0.01f;
    for (k = 0; k < 100; ++k) {
        vx = vx * d;
        vy = (vy - kGravity * (double)0.01f) * d;
        px += vx * (double)0.01f;
        py += vy * (double)0.01f;
    }
    CHECK(result.trajectory_size == 101);
    CHECK_NEAR(result.position.x, px, 1e-5); /* float steps against double ones: 1e-6 m per step at most */
    CHECK_NEAR(result.position.y, py, 1e-5);
    CHECK_NEAR(result.velocity.y, vy, 1e-5);

    /* What the game draws at 0.255 s: step 25 completed, halfway to step 26. */
    CHECK_STATUS(fs_rendered_position(points, 101, 0.01f, 0.255f, FS_RENDER_NONE, &drawn), FS_STATUS_OK);
    CHECK_NEAR(drawn.x, points[25].position.x, 1e-6);
    CHECK_STATUS(fs_rendered_position(points, 101, 0.01f, 0.255f, FS_RENDER_INTERPOLATE, &drawn), FS_STATUS_OK);
    CHECK_NEAR(drawn.x, points[24].position.x + 0.5 * (points[25].position.x - points[24].position.x), 1e-5);
    CHECK_STATUS(fs_rendered_position(points, 101, 0.01f, 0.255f, FS_RENDER_EXTRAPOLATE, &drawn), FS_STATUS_OK);
    CHECK_NEAR(drawn.y, points[25].position.y + 0.005 * points[25].velocity.y, 1e-5);

    /* Refusals. */
    CHECK_STATUS(fs_rendered_position(points, 101, 0.0f, 0.255f, FS_RENDER_NONE, &drawn), FS_STATUS_INVALID_STEP);
    CHECK_STATUS(fs_rendered_position(points, 0, 0.01f, 0.255f, FS_RENDER_NONE, &drawn), FS_STATUS_INVALID_STEP);
    CHECK_STATUS(fs_rendered_position(points, 101, 0.01f, NAN, FS_RENDER_NONE, &drawn), FS_STATUS_NON_FINITE_INPUT);
    CHECK_STATUS(fs_rendered_position(points, 101, 0.01f, 0.2f, 3, &drawn), FS_STATUS_INVALID_SETTING);
    CHECK_STATUS(fs_predict_projectile_with_profile(dvec3(0.0, 2.0, 0.0), vec3(4.0f, 3.0f, 0.0f), 1.0f, &settings, NULL,
                                                    NULL, points, 512, &result),
                 FS_STATUS_NULL_POINTER);
    profile.timestep = 0.0f;
    CHECK_STATUS(fs_validate_engine_profile(&profile), FS_STATUS_INVALID_STEP);
    CHECK(fs_trajectory_capacity_with_profile(1.0f, &settings, &profile) == 0);
    settings.method = FS_METHOD_EXACT; /* a bad profile is refused whatever the method */
    CHECK_STATUS(fs_predict_projectile_with_profile(dvec3(0.0, 2.0, 0.0), vec3(4.0f, 3.0f, 0.0f), 1.0f, &settings,
                                                    &profile, NULL, points, 512, &result),
                 FS_STATUS_INVALID_STEP);
    profile.timestep = 0.01f;
    profile.order = 5;
    CHECK_STATUS(fs_validate_engine_profile(&profile), FS_STATUS_INVALID_SETTING);
    profile.order = FS_DAMPING_ORDER_GRAVITY_THEN_DAMPING;
    profile.planar = 2;
    CHECK_STATUS(fs_validate_engine_profile(&profile), FS_STATUS_INVALID_SETTING);
    profile.planar = 0;
    profile.substeps = 0;
    CHECK_STATUS(fs_validate_engine_profile(&profile), FS_STATUS_INVALID_SETTING);
    profile.substeps = 1;
    profile.linear_damping = NAN;
    CHECK_STATUS(fs_validate_engine_profile(&profile), FS_STATUS_NON_FINITE_INPUT);
}

/* ---- Danger --------------------------------------------------------------------------------- */

/* A grenade in free flight from (0, 10, 0) at (3, 0, 0) m/s: on the parabola at every time. */
static void test_danger_projectile(void) {
    fs_projectile_settings settings = fs_projectile_settings_default();
    fs_trajectory_point points[512];
    fs_projectile_result result;
    fs_projectile_danger danger;
    fs_danger_zone zone;
    fs_danger_start start;
    fs_closest_approach approach;
    fs_dvec3 at;
    int32_t safe = -1;
    const double fuse = 2.0, g = kGravity;
    size_t n;
    CHECK_STATUS(fs_predict_projectile(dvec3(0.0, 10.0, 0.0), vec3(3.0f, 0.0f, 0.0f), (float)fuse, &settings, NULL,
                                       points, 512, &result),
                 FS_STATUS_OK);
    n = (size_t)result.trajectory_size;
    danger.fuse_time = (float)fuse;
    danger.blast_radius = 4.0f;
    danger.contact_radius = 0.0f;

    /* Between the points: the parabola itself. */
    CHECK_STATUS(fs_position_on_trajectory(points, n, 0.7f, &at), FS_STATUS_OK);
    CHECK_NEAR(at.x, 3.0 * 0.7, kTol);
    CHECK_NEAR(at.y, 10.0 - 0.5 * g * 0.7 * 0.7, kTol);

    /* The blast: centred where the grenade is at the fuse time. */
    CHECK_STATUS(fs_compute_danger_zone(points, n, &danger, &zone), FS_STATUS_OK);
    CHECK_NEAR(zone.center.x, 3.0 * fuse, kTol);
    CHECK_NEAR(zone.center.y, 10.0 - 0.5 * g * fuse * fuse, kTol);
    CHECK(zone.radius == 4.0f && zone.time == 2.0f);

    /* 3.9 m from the centre: unsafe from the fuse time on, safe before (no contact radius). */
    CHECK_STATUS(fs_is_point_safe(points, n, &danger, dvec3(zone.center.x, zone.center.y + 3.9, 0.0), 2.0f, &safe),
                 FS_STATUS_OK);
    CHECK(safe == 0);
    CHECK_STATUS(fs_is_point_safe(points, n, &danger, dvec3(zone.center.x, zone.center.y + 3.9, 0.0), 1.9f, &safe),
                 FS_STATUS_OK);
    CHECK(safe == 1);
    CHECK_STATUS(fs_find_danger_start(points, n, &danger, dvec3(zone.center.x, zone.center.y + 3.9, 0.0), &start),
                 FS_STATUS_OK);
    CHECK(start.ever == 1 && start.time == 2.0f);
    CHECK_STATUS(fs_find_danger_start(points, n, &danger, dvec3(zone.center.x, zone.center.y + 4.1, 0.0), &start),
                 FS_STATUS_OK);
    CHECK(start.ever == 0);

    /* The path passes through the point where it is at t = 0.5: reached then, not before. */
    CHECK_STATUS(fs_find_path_approach(points, n, dvec3(1.5, 10.0 - 0.5 * g * 0.25, 0.0), 0.0f, 0.0f, 2.0f, &start),
                 FS_STATUS_OK);
    CHECK(start.ever == 1);
    CHECK_NEAR(start.time, 0.5, 1e-4); /* a float point on the path: its rounding, over the speed */
    /* 1 m beside the path (across the plane of flight) at t = 0.7: closest there, 1 m away. */
    CHECK_STATUS(
        fs_find_closest_path_approach(points, n, dvec3(2.1, 10.0 - 0.5 * g * 0.49, 1.0), 0.0f, 2.0f, &approach),
        FS_STATUS_OK);
    CHECK_NEAR(approach.distance, 1.0, kTol);
    CHECK_NEAR(approach.time, 0.7, 1e-3); /* the distance is flat (quadratic) at its minimum */

    /* Refusals. */
    CHECK_STATUS(fs_position_on_trajectory(NULL, 3, 0.5f, &at), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_position_on_trajectory(points, 0, 0.5f, &at), FS_STATUS_INVALID_STEP);
    CHECK_STATUS(fs_compute_danger_zone(points, n, NULL, &zone), FS_STATUS_NULL_POINTER);
    danger.fuse_time = -1.0f;
    CHECK_STATUS(fs_compute_danger_zone(points, n, &danger, &zone), FS_STATUS_INVALID_FUSE);
    danger.fuse_time = (float)fuse;
    danger.blast_radius = NAN;
    CHECK_STATUS(fs_compute_danger_zone(points, n, &danger, &zone), FS_STATUS_NON_FINITE_INPUT);
    danger.blast_radius = 4.0f;
    CHECK_STATUS(fs_find_path_approach(points, n, dvec3(0.0, 0.0, 0.0), -1.0f, 0.0f, 2.0f, &start),
                 FS_STATUS_INVALID_RADIUS);
    points[1].event = 99;
    CHECK_STATUS(fs_compute_danger_zone(points, n, &danger, &zone), FS_STATUS_INVALID_SETTING);
    points[1].event = FS_EVENT_STEP;
    points[1].time = -5.0f; /* times must not decrease */
    CHECK_STATUS(fs_compute_danger_zone(points, n, &danger, &zone), FS_STATUS_INVALID_STEP);
}

/* A car (the default 1.8 x 1.4 x 4.4 m box) driving along +Z at 10 m/s, towards characters. */
static void test_danger_vehicle(void) {
    fs_vehicle_body car = fs_vehicle_body_default();
    fs_character_body person = fs_character_body_default();
    const fs_approach_settings settings = fs_approach_settings_default();
    fs_approach_settings bad = settings;
    fs_vehicle_contact contact;
    fs_closest_approach approach;
    float separation = 0.0f;
    CHECK(car.half_extents.x == 0.9f && car.half_extents.y == 0.7f && car.half_extents.z == 2.2f);
    CHECK(person.radius == 0.4f && settings.tolerance == 1e-3f && settings.max_evaluations == 65536u);
    car.state.velocity = vec3(0.0f, 0.0f, 10.0f);
    person.position = dvec3(0.0, 0.0, 20.0);

    /* Gap at t = 0: 20 - 2.2 (the box's front) - 0.4 (the radius). */
    CHECK_STATUS(fs_compute_vehicle_separation(&car, &person, 0.0f, &separation), FS_STATUS_OK);
    CHECK_NEAR(separation, 17.4, kTol);
    /* Contact when the front reaches 19.6: t = 1.74 s, never later, within the tolerance. */
    CHECK_STATUS(fs_find_vehicle_contact(&car, &person, 5.0f, &settings, &contact), FS_STATUS_OK);
    CHECK(contact.contact == 1);
    CHECK(contact.time <= 1.74f + 1e-6f && contact.time >= 1.74f - 1.1e-4f); /* tolerance 1 mm at 10 m/s */
    CHECK(contact.separation <= 1e-3f && contact.evaluations > 0);

    /* A character 5 m to the side: closest 5 - 0.9 - 0.4 = 3.7 m, first when the box's front
     * passes it: 10 t + 2.2 = 20, t = 1.78 s. */
    person.position = dvec3(5.0, 0.0, 20.0);
    CHECK_STATUS(fs_find_vehicle_contact(&car, &person, 5.0f, &settings, &contact), FS_STATUS_OK);
    CHECK(contact.contact == 0);
    CHECK_STATUS(fs_find_closest_vehicle_approach(&car, &person, 5.0f, &settings, &approach), FS_STATUS_OK);
    CHECK(approach.distance >= 3.7f - 1e-5f && approach.distance <= 3.7f + 1e-3f);
    /* Not later than 1.78 s, not earlier than when the separation first comes within the 1 mm
     * tolerance of 3.7: sqrt(4.1^2 + d^2) - 4.1 <= 1e-3 with the front d = 0.0906 m short. */
    CHECK(approach.time <= 1.78f + 1e-5f && approach.time >= 1.78f - 0.0091f);

    /* Refusals. */
    CHECK_STATUS(fs_compute_vehicle_separation(&car, &person, -1.0f, &separation), FS_STATUS_NEGATIVE_TIME);
    CHECK_STATUS(fs_compute_vehicle_separation(NULL, &person, 0.0f, &separation), FS_STATUS_NULL_POINTER);
    bad.tolerance = 0.0f;
    CHECK_STATUS(fs_find_vehicle_contact(&car, &person, 5.0f, &bad, &contact), FS_STATUS_INVALID_STEP);
    car.settings.frame = 7;
    CHECK_STATUS(fs_find_vehicle_contact(&car, &person, 5.0f, &settings, &contact), FS_STATUS_INVALID_SETTING);
    car.settings.frame = FS_FRAME_BODY;
    car.half_extents.y = 0.0f;
    CHECK_STATUS(fs_find_closest_vehicle_approach(&car, &person, 5.0f, &settings, &approach),
                 FS_STATUS_DEGENERATE_SHAPE);
}

/* ---- Throw planning ---------------------------------------------------------------------------- */

static void test_plan_throw(void) {
    fs_world* world = fs_world_create();
    const fs_plane plane = floor_plane();
    fs_throw_plan_request request = fs_throw_plan_request_default();
    fs_throw_plan plans[4];
    fs_trajectory_point scratch[1024];
    fs_trajectory_point points[1024];
    fs_throw_plan_result result;
    fs_projectile_result check;
    size_t i, scratch_size;
    CHECK(world != NULL);
    if (world == NULL) return;
    CHECK_STATUS(fs_world_add_plane(world, &plane, NULL), FS_STATUS_OK);
    CHECK(request.fuse_time == 3.0f && request.max_speed == 20.0f && request.max_plans == 3u);
    CHECK(request.budget.max_predictions == 400u && request.budget.seed_landing_fractions[4] == 1.0f);
    request.settings.friction = 0.4f;
    request.start = dvec3(0.0, 1.5, 0.0);
    request.target = dvec3(8.0, 0.0, 6.0);
    scratch_size = fs_throw_plan_scratch_size(&request);
    CHECK(scratch_size > 0 && scratch_size <= 1024);

    CHECK_STATUS(fs_plan_throw(&request, world, plans, 4, scratch, 1024, &result), FS_STATUS_OK);
    CHECK(result.plan_count >= 1 && result.plan_count <= 3);
    CHECK(result.predictions >= result.plan_count);
    for (i = 0; i < result.plan_count; ++i) {
        const fs_throw_plan* plan = &plans[i];
        const double dx = plan->final_position.x - 8.0, dy = plan->final_position.y, dz = plan->final_position.z - 6.0;
        const double speed =
            sqrt(plan->launch_velocity.x * plan->launch_velocity.x + plan->launch_velocity.y * plan->launch_velocity.y +
                 plan->launch_velocity.z * plan->launch_velocity.z);
        /* Within the acceptance radius, at a launch speed within the cap... */
        CHECK(plan->distance <= request.acceptance_radius);
        CHECK_NEAR(sqrt(dx * dx + dy * dy + dz * dz), plan->distance, kTol);
        CHECK(speed <= 20.0 + 1e-4);
        /* ... and the forward model agrees: predicting the plan ends where it says. */
        CHECK_STATUS(fs_predict_projectile(request.start, plan->launch_velocity, request.fuse_time, &request.settings,
                                           world, points, 1024, &check),
                     FS_STATUS_OK);
        CHECK(check.position.x == plan->final_position.x && check.position.y == plan->final_position.y &&
              check.position.z == plan->final_position.z);
        CHECK(check.bounces == plan->bounces);
    }

    /* Refusals. */
    CHECK_STATUS(fs_plan_throw(NULL, world, plans, 4, scratch, 1024, &result), FS_STATUS_NULL_POINTER);
    CHECK_STATUS(fs_plan_throw(&request, world, NULL, 4, scratch, 1024, &result), FS_STATUS_NULL_POINTER);
    request.fuse_time = 0.0f;
    CHECK_STATUS(fs_plan_throw(&request, world, plans, 4, scratch, 1024, &result), FS_STATUS_INVALID_FUSE);
    CHECK(fs_throw_plan_scratch_size(&request) == 0);
    request.fuse_time = 3.0f;
    request.settings.method = 9;
    CHECK_STATUS(fs_plan_throw(&request, world, plans, 4, scratch, 1024, &result), FS_STATUS_INVALID_SETTING);
    request.settings.method = FS_METHOD_EXACT;
    request.budget.refinements = 33;
    CHECK_STATUS(fs_plan_throw(&request, world, plans, 4, scratch, 1024, &result), FS_STATUS_INVALID_ITERATIONS);
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
    test_callback_world();
    test_meshes();
    test_engine_profiles();
    test_danger_projectile();
    test_danger_vehicle();
    test_plan_throw();
    test_aim();
    test_dead_reckoning();
    test_dead_reckoning_receiver();
    if (failures != 0) {
        fprintf(stderr, "c_api_test: %d check(s) failed\n", failures);
        return 1;
    }
    return 0;
}
