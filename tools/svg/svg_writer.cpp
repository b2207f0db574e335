#include "svg_writer.h"

#include <cmath>
#include <cstdio>

namespace foresight_cli {

namespace {

// The attributes after an element's own, with the space that separates them (none when empty).
// Built by appending (GCC 12 reports a false -Wrestrict for " " + std::string here).
std::string after(std::string_view attributes) {
    std::string out;
    if (!attributes.empty()) {
        out += ' ';
        out += attributes;
    }
    return out;
}

}  // namespace

std::string escapeXml(std::string_view text, bool quotes) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                if (quotes) {
                    out += "&quot;";
                    break;
                }
                [[fallthrough]];
            default:
                out += c;
        }
    }
    return out;
}

double gridStep(double span) {
    if (!(span > 0)) return 1;
    const double rough = span / 8;
    const double power = std::pow(10.0, std::floor(std::log10(rough)));
    for (const double m : {1.0, 2.0, 5.0, 10.0})
        if (m * power >= rough) return m * power;
    return 10 * power;
}

std::string SvgWriter::number(double value) const {
    if (mFiniteOnly && !std::isfinite(value)) value = 0.0;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", mDecimals, value);
    return buffer;
}

std::string SvgWriter::begin(double width, double height, const std::string* title) const {
    std::string out;
    if (title != nullptr) out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" + number(height) +
           "\" viewBox=\"0 0 " + number(width) + " " + number(height) + "\" font-family=\"sans-serif\">\n";
    if (title != nullptr) out += "<title>" + escapeXml(*title) + "</title>\n";
    return out + "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

std::string SvgWriter::line(Value x1, Value y1, Value x2, Value y2, std::string_view attributes) const {
    return "<line x1=\"" + value(x1) + "\" y1=\"" + value(y1) + "\" x2=\"" + value(x2) + "\" y2=\"" + value(y2) + "\"" +
           after(attributes) + "/>\n";
}

std::string SvgWriter::rect(Value x, Value y, Value width, Value height, std::string_view attributes) const {
    return "<rect x=\"" + value(x) + "\" y=\"" + value(y) + "\" width=\"" + value(width) + "\" height=\"" +
           value(height) + "\"" + after(attributes) + "/>\n";
}

std::string SvgWriter::circle(Value cx, Value cy, Value r, std::string_view attributes) const {
    return "<circle cx=\"" + value(cx) + "\" cy=\"" + value(cy) + "\" r=\"" + value(r) + "\"" + after(attributes) +
           "/>\n";
}

std::string SvgWriter::text(Value x, Value y, std::string_view attributes, std::string_view content) const {
    return "<text x=\"" + value(x) + "\" y=\"" + value(y) + "\"" + after(attributes) + ">" + std::string(content) +
           "</text>\n";
}

std::string SvgWriter::polyline(std::string_view attributes, std::string_view points) const {
    return "<polyline" + after(attributes) + " points=\"" + std::string(points) + "\"/>\n";
}

std::string SvgWriter::polygon(std::string_view points, std::string_view attributes) const {
    return "<polygon points=\"" + std::string(points) + "\"" + after(attributes) + "/>\n";
}

std::string SvgWriter::path(std::string_view d, std::string_view attributes) const {
    return "<path d=\"" + std::string(d) + "\"" + after(attributes) + "/>\n";
}

}  // namespace foresight_cli
