#include "svg.h"

#include "svg_writer.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace foresight_cli {

namespace {

constexpr double kWidth = 900;  // px, whole picture
constexpr double kMargin = 56;  // px, left and bottom of each panel (axis labels)
constexpr double kPanelWidth = kWidth - kMargin - 24;
constexpr double kMaxPanelHeight = 520;  // px
constexpr double kLegendLine = 18;       // px per legend entry

const char* const kFaithfulColours[] = {"#e67e22", "#c0392b", "#b9770e", "#d35400"};
const char* const kExactColours[] = {"#1f6fd1", "#16a085", "#6c3483", "#117a65"};
const char* const kEngineColours[] = {"#27ae60", "#7d9d0a", "#1e8449", "#58a618"};

// Coordinates with two decimals; never "nan" in the SVG (picture() keeps bounds drawable).
const SvgWriter kSvg(2, true);

std::string number(double value) { return kSvg.number(value); }

glm::dvec3 vec3(const Json& value, const glm::dvec3& fallback = glm::dvec3(0)) {
    if (!value.is_array() || value.size() != 3) return fallback;
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) {
        if (!value[static_cast<std::size_t>(i)].is_number()) return fallback;
        v[i] = value[static_cast<std::size_t>(i)].get<double>();
    }
    return v;
}

glm::dquat quat(const Json& value) {
    if (!value.is_object()) return glm::dquat(1, 0, 0, 0);
    const auto part = [&](const char* key, double fallback) {
        return value.contains(key) && value[key].is_number() ? value[key].get<double>() : fallback;
    };
    glm::dquat q;
    q.w = part("w", 1);
    q.x = part("x", 0);
    q.y = part("y", 0);
    q.z = part("z", 0);
    const double length = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!(length > 0) || !std::isfinite(length)) return glm::dquat(1, 0, 0, 0);
    return glm::dquat(q.w / length, q.x / length, q.y / length, q.z / length);
}

const Json& member(const Json& object, const char* key) {
    static const Json none;
    return object.is_object() && object.contains(key) ? object[key] : none;
}

/// One view: world axes (u, v) of the panel (u to the right, v up the page).
struct Panel {
    const char* title;
    int uAxis, vAxis;  // 0 x, 1 y, 2 z
    const char* uName;
    const char* vName;
    double u0, u1, v0, v1;    // world range
    double left, top, scale;  // px
    double height() const { return (v1 - v0) * scale; }
    double px(double u) const { return left + (u - u0) * scale; }
    double py(double v) const { return top + (v1 - v) * scale; }
    double px(const glm::dvec3& p) const { return px(p[uAxis]); }
    double py(const glm::dvec3& p) const { return py(p[vAxis]); }
    std::string point(const glm::dvec3& p) const { return kSvg.point(px(p), py(p)); }
};

/// Convex hull of 2D points (Andrew's monotone chain), counter-clockwise.
std::vector<glm::dvec2> hull(std::vector<glm::dvec2> points) {
    std::sort(points.begin(), points.end(),
              [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (points.size() < 3) return points;
    std::vector<glm::dvec2> h(2 * points.size());
    std::size_t k = 0;
    const auto cross = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    for (const auto& p : points) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p) <= 0) --k;
        h[k++] = p;
    }
    for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], points[i]) <= 0) --k;
        h[k++] = points[i];
    }
    h.resize(k - 1);
    return h;
}

std::string polygon(const Panel& panel, const std::vector<glm::dvec3>& corners, const std::string& style) {
    std::vector<glm::dvec2> points;
    for (const auto& c : corners) points.emplace_back(panel.px(c), panel.py(c));
    std::string out;
    for (const auto& p : hull(points)) out += kSvg.point(p.x, p.y) + " ";
    return kSvg.polygon(out, style);
}

std::vector<glm::dvec3> boxCorners(const glm::dvec3& center, const glm::dvec3& half, const glm::dquat& orientation) {
    std::vector<glm::dvec3> corners;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 local((i & 1) ? half.x : -half.x, (i & 2) ? half.y : -half.y, (i & 4) ? half.z : -half.z);
        corners.push_back(center + orientation * local);
    }
    return corners;
}

/// The part of the line a u + b v = c inside the panel's range, or nothing.
std::string planeLine(const Panel& panel, double a, double b, double c) {
    std::vector<glm::dvec2> points;
    if (std::abs(b) > 1e-9) {
        for (const double u : {panel.u0, panel.u1}) {
            const double v = (c - a * u) / b;
            if (v >= panel.v0 - 1e-9 && v <= panel.v1 + 1e-9) points.emplace_back(u, v);
        }
    }
    if (std::abs(a) > 1e-9) {
        for (const double v : {panel.v0, panel.v1}) {
            const double u = (c - b * v) / a;
            if (u >= panel.u0 - 1e-9 && u <= panel.u1 + 1e-9) points.emplace_back(u, v);
        }
    }
    if (points.size() < 2) return {};
    return kSvg.line(panel.px(points[0].x), panel.py(points[0].y), panel.px(points[1].x), panel.py(points[1].y),
                     "stroke=\"#7f8c8d\" stroke-width=\"2\"");
}

std::string axes(const Panel& panel) {
    std::string out;
    const double width = (panel.u1 - panel.u0) * panel.scale;
    out += kSvg.text(panel.left, panel.top - 8, "font-size=\"14\" font-weight=\"bold\"", panel.title);
    out += kSvg.rect(panel.left, panel.top, width, panel.height(), "fill=\"#fbfbfb\" stroke=\"#555\"");
    // Ticks are counted, never accumulated: far from the origin `t += step` may not advance t.
    const auto ticks = [&](double lo, double hi, auto&& draw) {
        const double step = gridStep(hi - lo);
        const double first = std::ceil(lo / step), last = std::floor(hi / step + 1e-9);
        if (!std::isfinite(first) || !std::isfinite(last) || last - first > 100.0) return;
        for (double k = first; k <= last; k += 1.0) {
            const double t = k * step;
            draw(std::abs(t) < 1e-12 ? 0.0 : t);
        }
    };
    char label[32];
    ticks(panel.u0, panel.u1, [&](double u) {
        out += kSvg.line(panel.px(u), panel.top, panel.px(u), panel.top + panel.height(), "stroke=\"#e3e3e3\"");
        std::snprintf(label, sizeof label, "%g", u);
        out +=
            kSvg.text(panel.px(u), panel.top + panel.height() + 16, "font-size=\"11\" text-anchor=\"middle\"", label);
    });
    ticks(panel.v0, panel.v1, [&](double v) {
        out += kSvg.line(panel.left, panel.py(v), panel.left + width, panel.py(v), "stroke=\"#e3e3e3\"");
        std::snprintf(label, sizeof label, "%g", v);
        out += kSvg.text(panel.left - 6, panel.py(v) + 4, "font-size=\"11\" text-anchor=\"end\"", label);
    });
    out += kSvg.text(panel.left + width / 2, panel.top + panel.height() + 34, "font-size=\"12\" text-anchor=\"middle\"",
                     std::string(panel.uName) + " [m]");
    out += kSvg.text(panel.left - 40, panel.top + panel.height() / 2,
                     "font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 " + number(panel.left - 40) + " " +
                         number(panel.top + panel.height() / 2) + ")\"",
                     std::string(panel.vName) + " [m]");
    return out;
}

struct Style {
    std::string colour;
    bool faithful = false;
    bool engine = false;  // an engine-matched flight: a thicker solid line, green shades
};

std::string world(const Panel& panel, const Json& document) {
    std::string out;
    const Json& w = member(document, "world");
    const glm::dvec3 middle =
        0.5 * (vec3(member(member(document, "bounds"), "min")) + vec3(member(member(document, "bounds"), "max")));
    const int other = 3 - panel.uAxis - panel.vAxis;  // the axis the view looks along
    for (const auto& plane : member(w, "planes")) {
        const glm::dvec3 n = vec3(member(plane, "normal"));
        const double d = member(plane, "distance").is_number() ? member(plane, "distance").get<double>() : 0.0;
        if (std::abs(n[other]) > 0.99) continue;  // seen face on: it fills the view
        out += planeLine(panel, n[panel.uAxis], n[panel.vAxis], d - n[other] * middle[other]);
    }
    const std::string meshStyle = "fill=\"#c8c8c8\" fill-opacity=\"0.35\" stroke=\"#9a9a9a\" stroke-width=\"0.3\"";
    for (const auto& mesh : member(w, "meshes")) {
        const Json& positions = member(mesh, "positions");
        const Json& indices = member(mesh, "indices");
        if (!positions.is_array() || !indices.is_array()) continue;
        const std::size_t vertexCount = positions.size() / 3;
        // One path per mesh (a subpath per triangle): a tenth of a pixel is enough, and the
        // file stays small for meshes of thousands of triangles.
        std::string d;
        char buffer[96];
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
            std::vector<glm::dvec3> corners;
            for (std::size_t k = 0; k < 3; ++k) {
                if (!indices[i + k].is_number_unsigned()) break;
                const auto index = indices[i + k].get<std::size_t>();
                if (index >= vertexCount) break;
                corners.emplace_back(positions[3 * index].get<double>(), positions[3 * index + 1].get<double>(),
                                     positions[3 * index + 2].get<double>());
            }
            if (corners.size() != 3) continue;
            std::snprintf(buffer, sizeof buffer, "M%.1f %.1fL%.1f %.1fL%.1f %.1fZ", panel.px(corners[0]),
                          panel.py(corners[0]), panel.px(corners[1]), panel.py(corners[1]), panel.px(corners[2]),
                          panel.py(corners[2]));
            d += buffer;
        }
        if (!d.empty()) out += kSvg.path(d, meshStyle);
    }
    const std::string solidStyle = "fill=\"#bdc3c7\" fill-opacity=\"0.6\" stroke=\"#7f8c8d\"";
    for (const auto& box : member(w, "boxes"))
        out += polygon(panel,
                       boxCorners(vec3(member(box, "center")), vec3(member(box, "half_extents")),
                                  quat(member(box, "orientation"))),
                       solidStyle);
    for (const auto& sphere : member(w, "spheres")) {
        const glm::dvec3 c = vec3(member(sphere, "center"));
        const double r = member(sphere, "radius").is_number() ? member(sphere, "radius").get<double>() : 0.0;
        out += kSvg.circle(panel.px(c), panel.py(c), r * panel.scale, solidStyle);
    }
    return out;
}

std::string predictions(const Panel& panel, const Json& document, const std::vector<Style>& styles) {
    std::string out;
    // Exact paths first, the article's dashed ones over them (where they coincide, both show).
    for (const bool faithfulPass : {false, true}) {
        std::size_t index = 0;
        for (const auto& prediction : member(document, "predictions")) {
            const Style& style = styles[index++];
            if (style.faithful != faithfulPass) continue;
            const Json& path = member(prediction, "path");
            if (!path.is_array() || path.empty()) continue;
            const bool vehicle = member(prediction, "model") == "vehicle";
            if (vehicle) {
                const glm::dvec3 half = vec3(member(prediction, "half_extents"), glm::dvec3(0.9, 0.7, 2.2));
                double lastGhost = -1;
                for (const auto& point : path) {
                    const double t = member(point, "t").is_number() ? member(point, "t").get<double>() : 0.0;
                    const bool last = &point == &path.back();
                    if (!last && t - lastGhost < 0.5) continue;
                    lastGhost = t;
                    out += polygon(
                        panel, boxCorners(vec3(member(point, "position")), half, quat(member(point, "orientation"))),
                        "fill=\"" + style.colour + "\" fill-opacity=\"" + (last ? "0.45" : "0.12") + "\" stroke=\"" +
                            style.colour + "\" stroke-width=\"1\"");
                }
            }
            std::string points;
            for (const auto& point : path) points += panel.point(vec3(member(point, "position"))) + " ";
            out += kSvg.polyline("fill=\"none\" stroke=\"" + style.colour + "\" stroke-width=\"" +
                                     (style.engine ? "3" : "2") + "\"" +
                                     (style.faithful ? " stroke-dasharray=\"7 4\"" : ""),
                                 points);
            for (const auto& point : path) {
                const Json& event = member(point, "event");
                const glm::dvec3 p = vec3(member(point, "position"));
                if (event == "bounce" || event == "hit") {
                    out += kSvg.circle(panel.px(p), panel.py(p), "3.5",
                                       "fill=\"white\" stroke=\"" + style.colour + "\" stroke-width=\"1.5\"");
                } else if (event == "rest") {
                    out += kSvg.rect(panel.px(p) - 4, panel.py(p) - 4, "8", "8", "fill=\"" + style.colour + "\"");
                }
            }
        }
    }
    return out;
}

/// Danger zones (docs/viewer-format.md): the blast sphere's outline in each view, translucent red.
std::string dangerZones(const Panel& panel, const Json& document) {
    std::string out;
    const Json& zones = member(document, "danger_zones");
    if (!zones.is_array()) return out;
    for (const auto& zone : zones) {
        const Json& radius = member(zone, "radius");
        if (!radius.is_number() || !(radius.get<double>() > 0.0)) continue;
        const glm::dvec3 c = vec3(member(zone, "center"));
        out += kSvg.circle(panel.px(c), panel.py(c), radius.get<double>() * panel.scale,
                           "fill=\"#d62728\" fill-opacity=\"0.12\" stroke=\"#d62728\" stroke-width=\"1.5\" "
                           "stroke-dasharray=\"4 3\"");
    }
    return out;
}

std::string picture(const Json& document) {
    glm::dvec3 lo = vec3(member(member(document, "bounds"), "min"), glm::dvec3(-10, 0, -10));
    glm::dvec3 hi = vec3(member(member(document, "bounds"), "max"), glm::dvec3(10, 2, 10));
    // A margin of 5% (at least 0.5 m) so that nothing sits on the frame.
    // Drawable bounds: finite, within +-1e12 m (far beyond the precision envelope of any
    // prediction), so that spans and scales stay finite; shapes beyond are clipped.
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(lo[axis])) lo[axis] = -10.0;
        if (!std::isfinite(hi[axis])) hi[axis] = 10.0;
        lo[axis] = std::clamp(lo[axis], -1e12, 1e12);
        hi[axis] = std::clamp(hi[axis], lo[axis], 1e12);
    }
    const glm::dvec3 pad =
        glm::max(0.05 * (hi - lo), glm::max(glm::dvec3(0.5), 1e-9 * glm::max(glm::abs(lo), glm::abs(hi))));
    lo -= pad;
    hi += pad;

    Panel top{"Top view", 0, 2, "x", "z", lo.x, hi.x, lo.z, hi.z, kMargin, 60, 1};
    top.scale = std::min(kPanelWidth / (hi.x - lo.x), kMaxPanelHeight / (hi.z - lo.z));
    Panel side{"Side view", 2, 1, "z", "y", lo.z, hi.z, lo.y, hi.y, kMargin, 0, 1};
    side.scale = std::min(kPanelWidth / (hi.z - lo.z), kMaxPanelHeight / (hi.y - lo.y));
    side.top = top.top + top.height() + 80;

    std::vector<Style> styles;
    std::size_t faithfulCount = 0, exactCount = 0, engineCount = 0;
    for (const auto& prediction : member(document, "predictions")) {
        Style style;
        style.faithful = member(prediction, "variant") == "faithful";
        style.engine = member(prediction, "variant") == "engine";
        style.colour = style.faithful ? kFaithfulColours[faithfulCount++ % 4]
                       : style.engine ? kEngineColours[engineCount++ % 4]
                                      : kExactColours[exactCount++ % 4];
        styles.push_back(style);
    }
    const double legendTop = side.top + side.height() + 60;
    const double height = legendTop + kLegendLine * static_cast<double>(styles.size() + 2) + 16;

    std::string title =
        member(document, "title").is_string() ? member(document, "title").get<std::string>() : "foresight";
    std::string out = kSvg.begin(kWidth, height, &title);
    out += kSvg.text(kMargin, "28", "font-size=\"18\"", escapeXml(title));
    for (const Panel* panel : {&top, &side}) {
        out += axes(*panel);
        // Everything inside the panel is clipped to it.
        const std::string id = panel == &top ? "top" : "side";
        out += "<clipPath id=\"" + id + "\">" +
               SvgWriter::inlined(
                   kSvg.rect(panel->left, panel->top, (panel->u1 - panel->u0) * panel->scale, panel->height(), "")) +
               "</clipPath>\n<g clip-path=\"url(#" + id + ")\">\n";
        out += world(*panel, document);
        out += dangerZones(*panel, document);
        out += predictions(*panel, document, styles);
        out += "</g>\n";
    }
    // Legend: one line per prediction, then the markers.
    double y = legendTop;
    std::size_t index = 0;
    for (const auto& prediction : member(document, "predictions")) {
        const Style& style = styles[index++];
        const std::string id = member(prediction, "id").is_string() ? member(prediction, "id").get<std::string>()
                                                                    : member(prediction, "id").dump();
        std::string method =
            member(prediction, "method").is_string() ? member(prediction, "method").get<std::string>() : "";
        if (style.engine && member(prediction, "engine").is_string())
            method = "as " + member(prediction, "engine").get<std::string>() + " steps it";
        out += kSvg.line(kMargin, y, kMargin + 36, y,
                         "stroke=\"" + style.colour + "\" stroke-width=\"" + (style.engine ? "3" : "2") + "\"" +
                             (style.faithful ? " stroke-dasharray=\"7 4\"" : ""));
        out += kSvg.text(
            kMargin + 44, y + 4, "font-size=\"12\"",
            escapeXml(id) + " (" + escapeXml(method) + (style.faithful ? ": the article's method" : "") + ")");
        y += kLegendLine;
    }
    // The markers' key: each marker and its name on one line.
    out +=
        SvgWriter::inlined(kSvg.circle(kMargin + 18, y, "3.5", "fill=\"white\" stroke=\"#333\" stroke-width=\"1.5\"")) +
        kSvg.text(kMargin + 44, y + 4, "font-size=\"12\"", "bounce");
    out += SvgWriter::inlined(kSvg.rect(kMargin + 160, y - 4, "8", "8", "fill=\"#333\"")) +
           kSvg.text(kMargin + 176, y + 4, "font-size=\"12\"", "at rest");
    if (member(document, "danger_zones").is_array() && !member(document, "danger_zones").empty()) {
        out += SvgWriter::inlined(kSvg.circle(kMargin + 300, y, "6",
                                              "fill=\"#d62728\" fill-opacity=\"0.12\" stroke=\"#d62728\" "
                                              "stroke-width=\"1.5\" stroke-dasharray=\"4 3\"")) +
               kSvg.text(kMargin + 316, y + 4, "font-size=\"12\"", "danger zone (blast)");
    }
    out += SvgWriter::end();
    return out;
}

}  // namespace

std::string svgPicture(const Json& document) {
    try {
        return picture(document);
    } catch (const std::exception& error) {  // a malformed document (nlohmann type errors)
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"600\" "
               "height=\"40\"><text x=\"10\" y=\"25\">cannot draw this document: " +
               escapeXml(error.what()) + "</text></svg>\n";
    }
}

}  // namespace foresight_cli
