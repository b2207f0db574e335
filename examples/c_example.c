#include <foresight/foresight_c.h>

#include <stdio.h>

int main(void) {
    if (fs_abi_version() != FS_ABI_VERSION) return 1; /* header and library must match */

    fs_world* world = fs_world_create(); /* a floor y = 0 */
    fs_plane floor_plane = {{0.0f, 1.0f, 0.0f}, 0.0f, 0.0};
    fs_world_add_plane(world, &floor_plane, NULL);

    fs_projectile_settings settings = fs_projectile_settings_default(); /* Exact, 9.81 m/s^2 */
    fs_trajectory_point points[512];                                    /* caller-owned */
    fs_projectile_result grenade;
    fs_dvec3 position = {0.0, 1.5, 0.0};
    fs_vec3 velocity = {0.0f, 4.0f, 12.0f};
    fs_status status = fs_predict_projectile(position, velocity, 3.0f, &settings, world, points, 512, &grenade);
    if (status != FS_STATUS_OK) printf("refused: %s\n", fs_status_message(status));
    /* grenade.position, .bounces, .at_rest; points[0 .. grenade.trajectory_size) to draw. */

    fs_world_destroy(world);
    return status == FS_STATUS_OK ? 0 : 1;
}
