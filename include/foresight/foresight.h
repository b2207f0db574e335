#pragma once
/// @file foresight.h
/// Everything of foresight's core library: include this, link foresight::foresight.

#include <foresight/aim.h>
#include <foresight/character.h>
#include <foresight/config.h>
#include <foresight/danger.h>
#include <foresight/dead_reckoning.h>
#include <foresight/engine_profile.h>
#include <foresight/obj_check.h>
#include <foresight/orientation.h>
#include <foresight/projectile.h>
#include <foresight/replication.h>
#include <foresight/static_world.h>
#include <foresight/status.h>
#include <foresight/throw_planner.h>
#include <foresight/vehicle.h>
#include <foresight/world.h>
