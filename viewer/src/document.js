// Reads the picture document (docs/viewer-format.md) from the page and checks it.
// Returns {document} with defaults filled in, or {problems: [...]} saying what is wrong.

const MAX_PROBLEMS = 12;
const DRAWN_MODELS = new Set(['projectile', 'vehicle', 'linear', 'accelerated']);
const VARIANTS = new Set(['faithful', 'exact', 'engine']);

export function readPictureDocument(page) {
    const element = page.getElementById('foresight-data');
    if (!element) {
        return { problems: ['This page holds no picture document: it has no script element '
            + 'with id "foresight-data" (type application/json).'] };
    }
    const text = element.textContent.trim();
    if (text === '') return { problems: ['The picture document in this page is empty.'] };
    let parsed;
    try {
        parsed = JSON.parse(text);
    } catch (error) {
        return { problems: [`The picture document is not valid JSON: ${error.message}`] };
    }
    const problems = [];
    const document = checkDocument(parsed, problems);
    if (problems.length > MAX_PROBLEMS) {
        const more = problems.length - MAX_PROBLEMS;
        problems.length = MAX_PROBLEMS;
        problems.push(`... and ${more} more`);
    }
    return problems.length ? { problems } : { document };
}

const isObject = (value) => value !== null && typeof value === 'object' && !Array.isArray(value);
const isNumber = (value) => typeof value === 'number' && Number.isFinite(value);
const isVec3 = (value) => Array.isArray(value) && value.length === 3 && value.every(isNumber);
const isQuat = (value) => isObject(value) && ['w', 'x', 'y', 'z'].every((k) => isNumber(value[k]))
    && Math.hypot(value.w, value.x, value.y, value.z) > 0;

// Small checkers that record a problem (with its JSON path) and return whether the value is good.
function expect(ok, problems, where, what) {
    if (!ok) problems.push(`${where}: ${what}`);
    return ok;
}
const vec3 = (object, key, problems, where) =>
    expect(isVec3(object[key]), problems, `${where}.${key}`, 'expected [x, y, z], three finite numbers');
const number = (object, key, problems, where, test = () => true, what = 'a finite number') =>
    expect(isNumber(object[key]) && test(object[key]), problems, `${where}.${key}`, `expected ${what}`);
function array(object, key, problems, where, optional) {
    if (object[key] === undefined && optional) return [];
    return expect(Array.isArray(object[key]), problems, `${where}.${key}`, 'expected an array')
        ? object[key] : [];
}
const quat = (object, key, problems, where) =>
    expect(isQuat(object[key]), problems, `${where}.${key}`,
        'expected {"w", "x", "y", "z"}, finite and not all zero');

function checkDocument(doc, problems) {
    if (!isObject(doc)) {
        problems.push('The picture document must be a JSON object.');
        return null;
    }
    if (doc.version !== 1) {
        problems.push(`version: expected 1, found ${JSON.stringify(doc.version)} `
            + '(this viewer reads version 1 of the picture document)');
    }
    const title = typeof doc.title === 'string' ? doc.title : 'foresight';
    const gravity = doc.gravity === undefined ? [0, -9.81, 0] : doc.gravity;
    expect(isVec3(gravity), problems, 'gravity', 'expected [x, y, z], three finite numbers');

    if (expect(isObject(doc.bounds), problems, 'bounds', 'expected {"min": [x, y, z], "max": [x, y, z]}')
        && vec3(doc.bounds, 'min', problems, 'bounds') && vec3(doc.bounds, 'max', problems, 'bounds')) {
        expect(doc.bounds.min.every((v, i) => v <= doc.bounds.max[i]), problems, 'bounds',
            'min must not exceed max');
    }

    const world = doc.world === undefined ? {} : doc.world;
    if (expect(isObject(world), problems, 'world', 'expected an object')) {
        array(world, 'planes', problems, 'world', true).forEach((plane, i) => {
            const where = `world.planes[${i}]`;
            if (!expect(isObject(plane), problems, where, 'expected an object')) return;
            if (vec3(plane, 'normal', problems, where)) {
                expect(Math.hypot(...plane.normal) > 0, problems, `${where}.normal`, 'must not be zero');
            }
            number(plane, 'distance', problems, where);
        });
        array(world, 'boxes', problems, 'world', true).forEach((box, i) => {
            const where = `world.boxes[${i}]`;
            if (!expect(isObject(box), problems, where, 'expected an object')) return;
            vec3(box, 'center', problems, where);
            if (vec3(box, 'half_extents', problems, where)) {
                expect(box.half_extents.every((v) => v > 0), problems, `${where}.half_extents`,
                    'must be positive');
            }
            if (box.orientation !== undefined) quat(box, 'orientation', problems, where);
        });
        array(world, 'spheres', problems, 'world', true).forEach((sphere, i) => {
            const where = `world.spheres[${i}]`;
            if (!expect(isObject(sphere), problems, where, 'expected an object')) return;
            vec3(sphere, 'center', problems, where);
            number(sphere, 'radius', problems, where, (r) => r > 0, 'a positive number');
        });
        array(world, 'meshes', problems, 'world', true).forEach((mesh, i) => {
            const where = `world.meshes[${i}]`;
            if (!expect(isObject(mesh), problems, where, 'expected an object')) return;
            const positions = array(mesh, 'positions', problems, where, false);
            const indices = array(mesh, 'indices', problems, where, false);
            expect(positions.length % 3 === 0 && positions.every(isNumber), problems,
                `${where}.positions`, 'expected finite numbers, 3 per vertex');
            const vertices = Math.floor(positions.length / 3);
            expect(indices.length % 3 === 0
                && indices.every((k) => Number.isInteger(k) && k >= 0 && k < vertices),
            problems, `${where}.indices`, `expected vertex indices (0 to ${vertices - 1}), 3 per triangle`);
        });
    }

    const predictions = [];
    array(doc, 'predictions', problems, '', true).forEach((prediction, i) => {
        const checked = checkPrediction(prediction, i, problems);
        if (checked) predictions.push(checked);
    });

    const dangerZones = [];
    array(doc, 'danger_zones', problems, '', true).forEach((zone, i) => {
        const where = `danger_zones[${i}]`;
        if (!expect(isObject(zone), problems, where, 'expected an object')) return;
        const ok = [vec3(zone, 'center', problems, where),
            number(zone, 'radius', problems, where, (r) => r > 0, 'a positive number'),
            zone.time === undefined || number(zone, 'time', problems, where)].every(Boolean);
        if (ok) {
            dangerZones.push({ id: String(zone.id ?? `zone ${i}`), center: zone.center,
                radius: zone.radius, time: zone.time ?? 0 });
        }
    });

    if (problems.length) return null;
    return {
        title, gravity, bounds: doc.bounds,
        world: { planes: world.planes ?? [], boxes: world.boxes ?? [], spheres: world.spheres ?? [],
            meshes: world.meshes ?? [] },
        predictions, dangerZones,
    };
}

// Returns the prediction to draw, or null for one that draws nothing (orientation, empty path).
function checkPrediction(prediction, i, problems) {
    const where = `predictions[${i}]`;
    if (!expect(isObject(prediction), problems, where, 'expected an object')) return null;
    if (prediction.model === 'orientation') return null;
    const id = typeof prediction.id === 'string' ? prediction.id : `prediction ${i}`;
    const good = [
        expect(DRAWN_MODELS.has(prediction.model), problems, `${where}.model`,
            `expected one of projectile, vehicle, linear, accelerated, orientation; found ${JSON.stringify(prediction.model)}`),
        expect(VARIANTS.has(prediction.variant), problems, `${where}.variant`,
            `expected "faithful", "exact" or "engine"; found ${JSON.stringify(prediction.variant)}`),
        prediction.engine === undefined || expect(typeof prediction.engine === 'string', problems, `${where}.engine`,
            'expected a string (the engine name)'),
        prediction.time === undefined || number(prediction, 'time', problems, where, (t) => t >= 0, 'a time >= 0'),
        prediction.radius === undefined || number(prediction, 'radius', problems, where, (r) => r >= 0, 'a radius >= 0'),
        prediction.half_extents === undefined || (vec3(prediction, 'half_extents', problems, where)
            && expect(prediction.half_extents.every((v) => v > 0), problems, `${where}.half_extents`, 'must be positive')),
    ].every(Boolean);
    const path = array(prediction, 'path', problems, where, false);
    let previousTime = -Infinity;
    let pathGood = true;
    path.forEach((point, k) => {
        const at = `${where}.path[${k}]`;
        if (!expect(isObject(point), problems, at, 'expected an object')) {
            pathGood = false;
            return;
        }
        const ok = [
            number(point, 't', problems, at) && expect(point.t >= previousTime, problems, `${at}.t`,
                'path times must not decrease'),
            vec3(point, 'position', problems, at),
            point.velocity === undefined || vec3(point, 'velocity', problems, at),
            point.normal === undefined || vec3(point, 'normal', problems, at),
            prediction.model !== 'vehicle' || quat(point, 'orientation', problems, at),
        ].every(Boolean);
        if (isNumber(point.t)) previousTime = Math.max(previousTime, point.t);
        pathGood &&= ok;
    });
    if (!good || !pathGood || path.length === 0) return null;
    return {
        id, model: prediction.model, method: String(prediction.method ?? prediction.model),
        variant: prediction.variant,
        engine: prediction.engine,
        time: prediction.time ?? path[path.length - 1].t,
        radius: prediction.radius ?? 0,
        halfExtents: prediction.half_extents ?? [0.9, 0.7, 2.2],
        path: path.map((point) => ({
            t: point.t, position: point.position, velocity: point.velocity ?? [0, 0, 0],
            event: String(point.event ?? 'step'), normal: point.normal,
            orientation: point.orientation,
        })),
    };
}
