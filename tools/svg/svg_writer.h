#pragma once
/// @file svg_writer.h
/// The one place that writes SVG markup: the elements the CLI's pictures use (`--svg`, svg.h)
/// and `foresight netsim --svg`'s error chart (netsim.h), with XML escaping and grid steps.
/// Target `foresight_svg_writer` (standard library only).

#include <string>
#include <string_view>

namespace foresight_cli {

/// `text` with `&`, `<`, `>` and, unless `quotes` is false, `"` written as entities: text and
/// attribute values of SVG, XML and HTML.
std::string escapeXml(std::string_view text, bool quotes = true);

/// A grid step of 1, 2 or 5 times a power of ten giving at most about eight lines over `span`
/// (1 when `span` is not > 0).
double gridStep(double span);

/// SVG elements as text, each ending with a newline. Coordinates and lengths print with a fixed
/// number of decimals; attributes after them (`attributes`: `stroke="#555"` ..., or empty) and
/// contents are written as given (escape text with escapeXml).
class SvgWriter {
public:
    /// A coordinate or length: a number (printed with the writer's decimals) or literal text.
    struct Value {
        Value(double value) : number(value) {}      // NOLINT: implicit on purpose
        Value(const char* text) : literal(text) {}  // NOLINT: "18", "100%"
        double number = 0;
        const char* literal = nullptr;
    };

    /// `decimals` digits after the point ("%.*f"); with `finiteOnly`, a value that is not finite
    /// prints as 0 (never "nan" in a picture).
    SvgWriter(int decimals, bool finiteOnly) : mDecimals(decimals), mFiniteOnly(finiteOnly) {}

    std::string number(double value) const;
    /// "x,y", a point of a polyline or polygon.
    std::string point(double x, double y) const { return number(x) + "," + number(y); }

    /// The start of a document: an XML declaration when `title` is given, the `<svg>` element
    /// (`width` x `height` px, sans-serif), the title and a white background.
    std::string begin(double width, double height, const std::string* title = nullptr) const;
    /// The end of a document.
    static std::string end() { return "</svg>\n"; }
    /// `element` without its newline, to put the next one on the same line.
    static std::string inlined(std::string element) {
        if (!element.empty() && element.back() == '\n') element.pop_back();
        return element;
    }

    std::string line(Value x1, Value y1, Value x2, Value y2, std::string_view attributes) const;
    std::string rect(Value x, Value y, Value width, Value height, std::string_view attributes) const;
    std::string circle(Value cx, Value cy, Value r, std::string_view attributes) const;
    std::string text(Value x, Value y, std::string_view attributes, std::string_view content) const;
    /// `<polyline ATTRIBUTES points="POINTS"/>`.
    std::string polyline(std::string_view attributes, std::string_view points) const;
    /// `<polygon points="POINTS" ATTRIBUTES/>`.
    std::string polygon(std::string_view points, std::string_view attributes) const;
    /// `<path d="D" ATTRIBUTES/>`.
    std::string path(std::string_view d, std::string_view attributes) const;

private:
    std::string value(const Value& v) const { return v.literal != nullptr ? std::string(v.literal) : number(v.number); }

    int mDecimals;
    bool mFiniteOnly;
};

}  // namespace foresight_cli
