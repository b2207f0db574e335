#pragma once
/// @file json_stream.h
/// A JSON writer that streams: values go in one at a time (begin an object, a key, a number,
/// ..., end it) and come out with exactly the bytes formatJson (json_output.h) prints for the
/// same document, numbers and layout alike, without the document ever being built.
///
/// formatJson puts a value on one line when it has at most 24 values in all and the line fits
/// in 200 columns at its indent, and one member per line otherwise. A value whose layout is
/// still open is written on one line and held back, with a token per value (at most 25), until
/// it ends (the line fits: kept as it is; else laid out again over lines) or holds more than 24
/// values (then it spans lines, and what it holds is laid out at once). So the memory held is
/// a few hundred bytes plus the finished text not yet handed to the sink (flushBytes), whatever
/// the size of the document.

#include "json_output.h"

#include <foresight/foresight.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace foresight_cli {

/// Appends `value` as formatJson prints jsonDouble(value) (must be finite): integral values
/// below 2^53 without a fraction, others as their shortest decimal (json_number.h).
void appendJsonDouble(std::string& out, double value);
/// Appends `value` as formatJson prints jsonFloat(value) (must be finite).
void appendJsonFloat(std::string& out, float value);
/// Appends `text` as a JSON string literal, as formatJson prints it (UTF-8 kept, control
/// characters escaped, invalid UTF-8 replaced by U+FFFD).
void appendJsonString(std::string& out, std::string_view text);

/// Streams one JSON document (the root value and a final newline) to a sink, laid out as
/// formatJson lays it out. Calls must form one well-formed value: `key` before each member of
/// an object, none in arrays; misuse is a programming error (checked by assertions in debug
/// builds only).
class JsonStreamWriter {
public:
    /// Receives finished text, in order; returns false when it could not take it (a closed pipe,
    /// a full disk), after which the writer drops everything and `failed()` is true.
    using Sink = std::function<bool(std::string_view text)>;

    /// Text is handed to `sink` in pieces of at least `flushBytes` bytes (the last one may be
    /// smaller), so nothing reaches the sink before that much is ready or the document ends.
    explicit JsonStreamWriter(Sink sink, std::size_t flushBytes = std::size_t(1) << 16);

    void beginObject();  ///< `{`, members follow as key, value pairs.
    void beginArray();   ///< `[`.
    void end();          ///< Closes the innermost open object or array.
    /// The next value's key in the enclosing object.
    void key(std::string_view name);

    void number(double value);                  ///< as jsonDouble(value); finite.
    void floatNumber(float value);              ///< as jsonFloat(value); finite.
    void integer(std::int64_t value);           ///< a JSON integer.
    void unsignedInteger(std::uint64_t value);  ///< a JSON integer.
    void boolean(bool value);                   ///< `true` or `false`.
    void string(std::string_view text);         ///< a JSON string (appendJsonString).
    /// Any parsed value, as formatJson prints it (objects and arrays member by member).
    void value(const Json& value);

    void position(const foresight::RVec3& position);     ///< [x, y, z] as jsonPosition.
    void vector(const foresight::Vec3& vector);          ///< [x, y, z] as jsonVector.
    void quaternion(const foresight::Quat& quaternion);  ///< {"w", "x", "y", "z"} as jsonQuaternion.
    /// A trajectory point as an element of the enclosing array: {"t": time, "position": [x, y,
    /// z], "velocity": [x, y, z], "event": event, "normal": [x, y, z]} ("normal" only when
    /// `normal` is not null), the very text beginObject, key("t"), floatNumber(time), ...,
    /// end() write. When the array already spans lines (from its third point on in a result) and
    /// the point fits on its line, the line is put together at once, without the per-value
    /// bookkeeping; otherwise it goes value by value.
    void trajectoryPoint(float time, const foresight::RVec3& position, const foresight::Vec3& velocity,
                         std::string_view event, const foresight::Vec3* normal);

    /// Hands the rest of the text to the sink; call once the root value has ended. Returns false
    /// if the sink refused any text (then nothing more was handed to it).
    bool finish();

    /// True once the sink refused text.
    bool failed() const { return mFailed; }
    /// Bytes handed to the sink so far.
    std::uint64_t bytesWritten() const { return mWritten; }

private:
    enum class Kind : std::uint8_t { Begin, End, Scalar };
    /// A value of a held frame. Offsets are into the held text: the inline form of the outermost
    /// held frame, from its opening bracket (mOut from mHeldStart, or mText once moved there).
    struct Token {
        Kind kind = Kind::Scalar;
        bool array = false;         ///< Begin/End: an array (else an object).
        std::uint32_t key = 0;      ///< its key's JSON text (members of objects).
        std::uint32_t keySize = 0;  ///< 0: no key.
        std::uint32_t text = 0;     ///< Scalar: its text; Begin: its opening bracket.
        std::uint32_t textSize = 0;
        std::uint32_t nodes = 1;   ///< Begin: values in the container, itself included (set at its end).
        std::uint32_t length = 1;  ///< Begin: tokens up to and including its End (set at its end).
    };
    /// An open object or array.
    struct Frame {
        bool array = false;
        bool multiLine = false;    ///< known to span lines: its opening is written, members go out as they come.
        bool empty = true;         ///< no member written yet.
        std::uint32_t nodes = 1;   ///< values so far, itself included (held frames only).
        std::uint32_t indent = 0;  ///< columns before its first character's line.
        std::uint32_t token = 0;   ///< held frames: index of its Begin token.
    };
    /// A number's text, remembered by its bits (trajectories repeat times and velocities).
    struct CachedNumber {
        std::uint64_t bits = 0;
        char text[31] = {};
        std::uint8_t size = 0;  ///< 0: empty.
    };

    /// Writes number(value)'s text at `out` (kJsonNumberChars of room: a cached text is copied as
    /// 32 bytes, its size byte included, and ends where its size says), from the cache when it
    /// holds it (else converted and remembered); returns its end.
    char* cachedDouble(char* out, double value);
    /// The same for floatNumber(value).
    char* cachedFloat(char* out, float value);
    /// The text cached in `cache` for `bits`, else the one `write(out)` writes (remembered).
    template <class Write>
    char* cachedText(std::vector<CachedNumber>& cache, std::uint64_t bits, char* out, Write write);
    /// Writes a number's text (written at a buffer by `write`) as a value.
    template <class Write>
    void numberValue(Write write);
    /// trajectoryPoint's value-by-value form.
    void trajectoryPointValues(float time, const foresight::RVec3& position, const foresight::Vec3& velocity,
                               std::string_view event, const foresight::Vec3* normal);
    bool holding() const { return mFirstHeld < mFrames.size(); }
    /// Writes what comes before a value (separator, indent, key); returns where the value starts.
    std::size_t openValue();
    /// Records the value written from `at` (a scalar, or the bracket of a container).
    void closeValue(Kind kind, bool array, std::size_t at);
    void scalar(std::string_view text);
    void begin(bool array);
    void writePrefix(Frame& parent, std::string_view key);
    void moveHeldText();
    void spanLines(std::size_t frame);
    void layout(std::size_t token, std::size_t indent);
    void writeInline(std::size_t token);
    void maybeFlush();
    std::string_view textOf(std::uint32_t at, std::uint32_t size) const {
        return std::string_view(mText).substr(at, size);
    }

    Sink mSink;
    std::size_t mFlushBytes;
    std::string mOut;            ///< finished text not yet handed to the sink, then the held text (from mHeldStart).
    std::string mText;           ///< the held text while a layout is decided from it.
    std::string mKey;            ///< the next value's key (JSON text), empty in arrays.
    std::size_t mKeyAt = 0;      ///< where the value's key was written in the held text.
    std::size_t mHeldStart = 0;  ///< where the held text starts in mOut.
    std::vector<Token> mTokens;  ///< held values, from the Begin of the outermost held frame.
    std::vector<Frame> mFrames;  ///< open containers, outermost first; multi-line ones first.
    std::size_t mFirstHeld = 0;  ///< index in mFrames of the outermost held frame.
    std::vector<CachedNumber> mFloats;   ///< floatNumber's texts by bits.
    std::vector<CachedNumber> mDoubles;  ///< number's texts by bits.
    std::uint64_t mWritten = 0;
    bool mFailed = false;
};

}  // namespace foresight_cli
