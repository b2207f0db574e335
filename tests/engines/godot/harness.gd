# Godot 3 engine harness (see ../README.md for the case and result formats).
#
# Run by run_godot.sh as a script MainLoop (`godot3-server --path PROJECT -s res://harness.gd`)
# inside a throw-away project whose project.godot sets physics/common/physics_fps and
# physics/3d/physics_engine. Everything is passed through environment variables:
#
#   FORESIGHT_MODE=plan   FORESIGHT_CASES=cases.json
#       prints one line "FORESIGHT_GROUP <fps> <engine>" per (physics_fps, engine) group of the
#       godot3 / godot3-bullet cases (and nothing else on lines starting that way).
#   FORESIGHT_MODE=run    FORESIGHT_CASES=cases.json FORESIGHT_OUT=part.txt
#                         FORESIGHT_FPS=60 FORESIGHT_ENGINE=godot3|godot3-bullet
#       runs the cases of that group (each in its own World, all in the same process, stepped
#       together) and writes one line per case: "<case index>\t<result object as JSON>".
#   FORESIGHT_MODE=merge  FORESIGHT_CASES=cases.json FORESIGHT_PARTS="a.txt:b.txt"
#                         FORESIGHT_OUT=out.json
#       writes the result file: every godot case's result in case-file order, `skipped`, and
#       `engine_versions`.
#
# Any failure quits with a non-zero exit code and a line "FORESIGHT_ERROR: ..." on stderr. (A
# GDScript parse error makes Godot exit 0 without running anything: run_godot.sh also checks
# that the expected output file was written.)
#
# Measurement: the state of case k's body is read in _iteration(), which Godot's main loop calls
# once per physics tick after flush_queries() and BEFORE that tick's PhysicsServer.step(); so
# the n-th call (n = 0, 1, ...) sees the state after n steps. The state is read from
# PhysicsServer.body_get_direct_state() (the physics server's own values, real_t = float in
# Godot 3); numbers are printed as the exact decimal expansion of those floats, so they read
# back exactly. When the longest case has its last row, the harness quits from _iteration,
# which makes Godot leave the tick before stepping again.
extends SceneTree

const GODOT_ENGINES = ["godot3", "godot3-bullet"]

var cases = []          # the case file's cases (all engines)
var runs = []           # {index, case, steps, rid, positions, velocities, angular_velocities}
var tick = 0
var max_steps = 0
var out_path = ""
var finished = false


func fail(message):
	printerr("FORESIGHT_ERROR: " + message)
	finished = true
	quit(2)


func _initialize():
	var mode = OS.get_environment("FORESIGHT_MODE")
	if not load_cases(OS.get_environment("FORESIGHT_CASES")):
		return
	if mode == "plan":
		plan()
	elif mode == "run":
		start_run()
	elif mode == "merge":
		merge()
	else:
		fail("FORESIGHT_MODE must be plan, run or merge (got '%s')" % mode)


func _iteration(_delta):
	if finished:
		return true
	record()
	return finished


# --- case file -----------------------------------------------------------------------------

func load_cases(path):
	if path == "":
		fail("FORESIGHT_CASES is not set")
		return false
	var file = File.new()
	if file.open(path, File.READ) != OK:
		fail("cannot read the case file " + path)
		return false
	var text = file.get_as_text()
	file.close()
	var parsed = JSON.parse(text)
	if parsed.error != OK:
		fail("%s: JSON error at line %d: %s" % [path, parsed.error_line, parsed.error_string])
		return false
	if typeof(parsed.result) != TYPE_DICTIONARY or not parsed.result.has("cases") \
			or typeof(parsed.result["cases"]) != TYPE_ARRAY:
		fail(path + ": expected an object with a \"cases\" array")
		return false
	cases = parsed.result["cases"]
	for i in range(cases.size()):
		var c = cases[i]
		if typeof(c) != TYPE_DICTIONARY or not c.has("id") or not c.has("engine"):
			fail("%s: case %d has no id or engine" % [path, i])
			return false
		if c["engine"] in GODOT_ENGINES:
			if not validate_case(c):
				return false
	return true


func validate_case(c):
	var id = str(c["id"])
	for key in ["timestep", "steps", "gravity", "body"]:
		if not c.has(key):
			fail("case %s: missing \"%s\"" % [id, key])
			return false
	var ts = c["timestep"]
	if typeof(ts) != TYPE_REAL or ts <= 0.0 or round(1.0 / ts) < 1.0:
		fail("case %s: timestep must be a positive number <= 1" % id)
		return false
	if typeof(c["steps"]) != TYPE_REAL or c["steps"] < 0 or c["steps"] != floor(c["steps"]):
		fail("case %s: steps must be a non-negative integer" % id)
		return false
	var body = c["body"]
	if typeof(body) != TYPE_DICTIONARY:
		fail("case %s: body must be an object" % id)
		return false
	for key in ["radius", "mass", "position", "velocity"]:
		if not body.has(key):
			fail("case %s: body has no \"%s\"" % [id, key])
			return false
	return true


func case_fps(c):
	return int(round(1.0 / c["timestep"]))


func vec3(value, what):
	if typeof(value) != TYPE_ARRAY or value.size() != 3:
		fail(what + " must be an array of 3 numbers")
		return Vector3()
	return Vector3(value[0], value[1], value[2])


# --- plan ------------------------------------------------------------------------------------

func plan():
	var seen = {}
	for c in cases:
		if c["engine"] in GODOT_ENGINES:
			var key = "%d %s" % [case_fps(c), c["engine"]]
			if not seen.has(key):
				seen[key] = true
				print("FORESIGHT_GROUP " + key)
	finished = true
	quit(0)


# --- run -------------------------------------------------------------------------------------

func start_run():
	out_path = OS.get_environment("FORESIGHT_OUT")
	var engine = OS.get_environment("FORESIGHT_ENGINE")
	var fps = int(OS.get_environment("FORESIGHT_FPS"))
	if out_path == "" or not (engine in GODOT_ENGINES) or fps < 1:
		fail("run mode needs FORESIGHT_OUT, FORESIGHT_ENGINE (godot3, godot3-bullet) and FORESIGHT_FPS")
		return
	# The project must really be set up for this group: the physics server and the tick rate are
	# chosen once at start-up (an unknown physics_engine name falls back to the default server).
	var server = PhysicsServer.get_class()
	var want = "BulletPhysicsServer" if engine == "godot3-bullet" else "PhysicsServerSW"
	if server != want:
		fail("engine %s needs the %s physics server, Godot runs %s" % [engine, want, server])
		return
	if Engine.iterations_per_second != fps:
		fail("physics_fps is %d, expected %d" % [Engine.iterations_per_second, fps])
		return
	for i in range(cases.size()):
		var c = cases[i]
		if c["engine"] == engine and case_fps(c) == fps:
			if not spawn(i, c):
				return
	if runs.empty():
		fail("no case for engine %s at %d Hz" % [engine, fps])


# One case: its own World (own physics space) under its own Viewport, so that cases stepped in
# the same process never meet.
func spawn(index, c):
	var id = str(c["id"])
	var viewport = Viewport.new()
	viewport.world = World.new()
	viewport.size = Vector2(2, 2)
	get_root().add_child(viewport)

	# Gravity of the space's default area: magnitude 1 along the case's gravity vector, so the
	# engine's gravity is the case's vector itself (magnitude * vector in float, exact with 1).
	var space = viewport.world.space
	var gravity = vec3(c["gravity"], "case %s: gravity" % id)
	if finished:
		return false
	PhysicsServer.area_set_param(space, PhysicsServer.AREA_PARAM_GRAVITY, 1.0)
	PhysicsServer.area_set_param(space, PhysicsServer.AREA_PARAM_GRAVITY_VECTOR, gravity)

	if c.has("boxes"):
		for b in c["boxes"]:
			var box = StaticBody.new()
			var half = vec3(b["half_extents"], "case %s: half_extents" % id)
			var center = vec3(b["center"], "case %s: center" % id)
			if finished:
				return false
			var basis = Basis()
			if b.has("rotation"):
				var q = b["rotation"]
				basis = Basis(Quat(q[0], q[1], q[2], q[3]))
			box.transform = Transform(basis, center)
			var box_material = PhysicsMaterial.new()
			box_material.bounce = b.get("restitution", 0.0)
			box_material.friction = b.get("friction", 1.0)
			box.physics_material_override = box_material
			var box_shape = BoxShape.new()
			box_shape.extents = half
			# The rounding is Bullet's collision margin (GodotPhysics has none: sharp boxes only).
			if b.has("rounding"):
				var rounding = float(b["rounding"])
				var smallest = min(half.x, min(half.y, half.z))
				if rounding < 0.0 or rounding > smallest:
					fail("case %s: rounding must be from 0 to the smallest half extent" % id)
					return false
				if rounding > 0.0 and c["engine"] != "godot3-bullet":
					fail("case %s: rounding must be 0: %s builds sharp boxes" % [id, c["engine"]])
					return false
				box_shape.margin = rounding
			var box_collision = CollisionShape.new()
			box_collision.shape = box_shape
			box.add_child(box_collision)
			viewport.add_child(box)

	# The body: a RigidBody as a game makes one, every property not named by the case at Godot's
	# default (PhysicsMaterial rough/absorbent off, Shape margin 0.04, continuous_cd off). Damping:
	# a linear_damp/angular_damp of -1 (the default) means the project's default damping (0.1 in
	# a new project). Measured on 3.2.3: GodotPhysics uses the body's value INSTEAD of the
	# project's when it is >= 0, but Godot's Bullet backend ADDS the body's value to the
	# project's, so with godot3-bullet a body damping of 0 still damps at 0.1. Both damp as
	# v *= 1 - dt * damp per step. Bounce combines as clamp(b1 + b2, 0, 1) in both servers.
	var body_case = c["body"]
	var body = RigidBody.new()
	body.mass = body_case["mass"]
	body.can_sleep = false
	if body_case.has("linear_damping"):
		body.linear_damp = body_case["linear_damping"]
	if body_case.has("angular_damping"):
		body.angular_damp = body_case["angular_damping"]
	var material = PhysicsMaterial.new()
	material.bounce = body_case.get("restitution", 0.0)
	material.friction = body_case.get("friction", 1.0)
	body.physics_material_override = material
	var sphere = SphereShape.new()
	sphere.radius = body_case["radius"]
	var collision = CollisionShape.new()
	collision.shape = sphere
	body.add_child(collision)
	body.transform = Transform(Basis(), vec3(body_case["position"], "case %s: position" % id))
	# Spawned as a game spawns a projectile: velocities set, then added to the scene.
	body.linear_velocity = vec3(body_case["velocity"], "case %s: velocity" % id)
	if body_case.has("angular_velocity"):
		body.angular_velocity = vec3(body_case["angular_velocity"], "case %s: angular_velocity" % id)
	if finished:
		return false
	viewport.add_child(body)

	var steps = int(c["steps"])
	max_steps = max(max_steps, steps)
	runs.append({"index": index, "case": c, "steps": steps, "rid": body.get_rid(),
			"positions": [], "velocities": [], "angular_velocities": []})
	return true


# Called once per tick before the tick's physics step: row `tick` = the state after `tick` steps.
func record():
	for r in runs:
		if tick > r["steps"]:
			continue
		var state = PhysicsServer.body_get_direct_state(r["rid"])
		if state == null:
			fail("case %s: no direct body state" % str(r["case"]["id"]))
			return
		r["positions"].append(vec_json(state.transform.origin))
		r["velocities"].append(vec_json(state.linear_velocity))
		r["angular_velocities"].append(vec_json(state.angular_velocity))
	if tick >= max_steps:
		write_run()
		finished = true
		quit(0)
		return
	tick += 1


func write_run():
	var file = File.new()
	if file.open(out_path, File.WRITE) != OK:
		fail("cannot write " + out_path)
		return
	for r in runs:
		var c = r["case"]
		var line = "{\"id\": %s, \"engine\": %s,\n \"positions\": [%s],\n \"velocities\": [%s],\n \"angular_velocities\": [%s]}" % [
				JSON.print(c["id"]), JSON.print(c["engine"]),
				PoolStringArray(r["positions"]).join(", "),
				PoolStringArray(r["velocities"]).join(", "),
				PoolStringArray(r["angular_velocities"]).join(", ")]
		# One record per line: newlines inside the object are escaped as \n text by replace().
		file.store_string("%d\t%s\n" % [r["index"], line.replace("\n", " ")])
	file.close()


# --- merge -----------------------------------------------------------------------------------

func merge():
	out_path = OS.get_environment("FORESIGHT_OUT")
	var parts = OS.get_environment("FORESIGHT_PARTS")
	if out_path == "":
		fail("merge mode needs FORESIGHT_OUT")
		return
	var by_index = {}
	if parts != "":
		for part in parts.split(":", false):
			var file = File.new()
			if file.open(part, File.READ) != OK:
				fail("cannot read " + part)
				return
			while not file.eof_reached():
				var line = file.get_line()
				if line == "":
					continue
				var tab = line.find("\t")
				by_index[int(line.substr(0, tab))] = line.substr(tab + 1, line.length() - tab - 1)
			file.close()
	var results = []
	var skipped = []
	var engines = {}
	for i in range(cases.size()):
		var c = cases[i]
		if c["engine"] in GODOT_ENGINES:
			if not by_index.has(i):
				fail("no result for case " + str(c["id"]))
				return
			results.append(by_index[i])
			engines[c["engine"]] = true
		else:
			skipped.append(JSON.print(c["id"]))
	var info = Engine.get_version_info()
	var version = "%d.%d.%d.%s.%s" % [info["major"], info["minor"], info["patch"], info["status"], info["build"]]
	var versions = []
	if engines.has("godot3"):
		versions.append("\"godot3\": %s" % JSON.print(version + " GodotPhysics"))
	if engines.has("godot3-bullet"):
		# Godot 3.2's Bullet backend is the Bullet bundled in its source tree (thirdparty/bullet,
		# 2.89 for 3.2.x); the Debian build links no system libBullet.
		versions.append("\"godot3-bullet\": %s" % JSON.print(version + " Bullet 2.89 (bundled)"))
	var text = "{\"engine_versions\": {%s},\n\"skipped\": [%s],\n\"results\": [\n%s\n]}\n" % [
			PoolStringArray(versions).join(", "), PoolStringArray(skipped).join(", "),
			PoolStringArray(results).join(",\n")]
	var out = File.new()
	if out.open(out_path, File.WRITE) != OK:
		fail("cannot write " + out_path)
		return
	out.store_string(text)
	out.close()
	finished = true
	quit(0)


# --- exact numbers ---------------------------------------------------------------------------

func vec_json(v):
	return "[%s, %s, %s]" % [exact(v.x), exact(v.y), exact(v.z)]


# The exact decimal expansion of a finite double (here always a float widened to double):
# x = m / 2^k with an integer m, so x = m * 5^k / 10^k. The digits of m * 5^k are computed in
# base 10^9 limbs. Reading the text back into a double or a float gives x exactly.
const LIMB = 1000000000
const FIVE_POW_13 = 1220703125

func exact(x):
	if is_nan(x) or is_inf(x):
		return "null"
	if x == 0.0:
		return "0"
	var negative = x < 0.0
	var a = abs(x)
	var k = 0
	while a != floor(a):
		a *= 2.0
		k += 1
	while a >= 4503599627370496.0 and fmod(a, 2.0) == 0.0:  # 2^52: keep m an exact int
		a /= 2.0
		k -= 1
	var limbs = [int(a) % LIMB, int(a) / LIMB]
	if k > 0:
		var left = k
		while left > 0:
			var n = min(left, 13)
			multiply(limbs, int(pow(5, n)) if n < 13 else FIVE_POW_13)
			left -= n
	else:
		for _i in range(-k):
			multiply(limbs, 2)
	var digits = limbs_to_string(limbs)
	if k > 0:
		while digits.length() <= k:
			digits = "0" + digits
		var whole = digits.substr(0, digits.length() - k)
		var fraction = digits.substr(digits.length() - k, k)
		while fraction.ends_with("0"):
			fraction = fraction.substr(0, fraction.length() - 1)
		digits = whole if fraction == "" else whole + "." + fraction
	return ("-" if negative else "") + digits


func multiply(limbs, factor):
	var carry = 0
	for i in range(limbs.size()):
		var product = limbs[i] * factor + carry
		limbs[i] = product % LIMB
		carry = product / LIMB
	while carry > 0:
		limbs.append(carry % LIMB)
		carry /= LIMB


func limbs_to_string(limbs):
	var top = limbs.size() - 1
	while top > 0 and limbs[top] == 0:
		top -= 1
	var text = str(limbs[top])
	for i in range(top - 1, -1, -1):
		text += "%09d" % limbs[i]
	return text
