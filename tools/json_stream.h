#pragma once
/// @file json_stream.h
/// A JSON writer that streams: values go in one at a time (begin an object, a key, a number,
/// ..., end it) and come out with exactly the bytes formatJson (json_output.h) prints for the
/// same document, numbers and layout alike, without the document ever being built.
///
/// formatJson puts a value on one line when it has at most 24 values in all and the line fits
/// in 200 columns at its indent, and one member per line otherwise. A value whose count is
/// still open is held back (as tokens, at most 25 values deep in each open value); once it has
/// more than 24 values it is known to span lines, and what it holds is written at once. So the
/// memory held is a few hundred bytes plus the finished text not yet handed to the sink
/// (flushBytes), whatever the size of the document.

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
/// below 2^53 without a fraction, others as nlohmann::json prints a double.
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

    /// Hands the rest of the text to the sink; call once the root value has ended. Returns false
    /// if the sink refused any text (then nothing more was handed to it).
    bool finish();

    /// True once the sink refused text.
    bool failed() const { return mFailed; }
    /// Bytes handed to the sink so far.
    std::uint64_t bytesWritten() const { return mWritten; }

private:
    enum class Kind : std::uint8_t { Begin, End, Scalar };
    /// A value held back while its container's layout is open. Texts are ranges of mText.
    struct Token {
        Kind kind = Kind::Scalar;
        bool array = false;         ///< Begin/End: an array (else an object).
        std::uint32_t key = 0;      ///< its key's JSON text in mText (members of objects).
        std::uint32_t keySize = 0;  ///< 0: no key.
        std::uint32_t text = 0;     ///< Scalar: its JSON text in mText.
        std::uint32_t textSize = 0;
        std::uint32_t nodes = 1;   ///< Begin: values in the container, itself included (set at its end).
        std::uint32_t length = 1;  ///< Begin: tokens up to and including its End (set at its end).
    };
    /// An open object or array.
    struct Frame {
        bool array = false;
        bool multiLine = false;    ///< known to span lines: its opening is written, members go out as they end.
        bool empty = true;         ///< multiLine: no member written yet.
        std::uint32_t nodes = 1;   ///< values so far, itself included (held frames only).
        std::uint32_t indent = 0;  ///< columns before its first character's line.
        std::uint32_t token = 0;   ///< held frames: index of its Begin token.
    };

    void scalar(std::string_view text);
    void begin(bool array);
    /// A new value: the prefix in a multi-line parent, or a token in a held one.
    bool startValue(Kind kind, bool array, std::string_view text);
    void writePrefix(Frame& parent, std::string_view key);
    void spanLines(std::size_t frame);
    void layout(std::size_t token, std::size_t indent);
    void writeInline(std::size_t token);
    void endDocument();
    void maybeFlush();
    std::uint32_t keep(std::string_view text);

    Sink mSink;
    std::size_t mFlushBytes;
    std::string mOut;            ///< finished text not yet handed to the sink.
    std::string mText;           ///< texts of the held tokens.
    std::string mKey;            ///< the next value's key (JSON text), empty in arrays.
    std::string mScratch;        ///< number text.
    std::vector<Token> mTokens;  ///< held values, from the Begin of the outermost held frame.
    std::vector<Frame> mFrames;  ///< open containers, outermost first; multi-line ones first.
    std::size_t mFirstHeld = 0;  ///< index in mFrames of the outermost held frame.
    std::uint64_t mWritten = 0;
    bool mFailed = false;
};

}  // namespace foresight_cli
