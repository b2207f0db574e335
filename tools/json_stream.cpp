#include "json_stream.h"

#include "json_number.h"

#include <bit>
#include <cassert>
#include <charconv>
#include <cstddef>
#include <cstring>
#include <system_error>
#include <utility>

namespace foresight_cli {

namespace {

// formatJson's layout (json_output.cpp): one line for at most kInlineNodes values whose line
// ends within kLineWidth columns.
constexpr std::uint32_t kInlineNodes = 24;
constexpr std::size_t kLineWidth = 200;

void appendInteger(std::string& out, auto value) {
    char buffer[24];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, static_cast<std::size_t>(written.ptr - buffer));
}

}  // namespace

void appendJsonDouble(std::string& out, double value) {
    // The text formatJson prints for jsonDouble(value) (json_number.h).
    char buffer[kJsonNumberChars];
    out.append(buffer, static_cast<std::size_t>(writeJsonDouble(buffer, value) - buffer));
}

void appendJsonFloat(std::string& out, float value) {
    char buffer[kJsonNumberChars];
    out.append(buffer, static_cast<std::size_t>(writeJsonFloat(buffer, value) - buffer));
}

void appendJsonString(std::string& out, std::string_view text) {
    // Printable ASCII without quotes or backslashes prints as it is; anything else (escapes,
    // UTF-8 to validate) goes through nlohmann's serializer, as formatJson does.
    bool plain = true;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u > 0x7e || c == '"' || c == '\\') {
            plain = false;
            break;
        }
    }
    if (plain) {
        out += '"';
        out += text;
        out += '"';
        return;
    }
    out += Json(std::string(text)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

namespace {

constexpr std::size_t kCacheBits = 10;  // 1024 texts per kind, 40 KiB each

std::size_t cacheSlot(std::uint64_t bits) {
    return static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ULL) >> (64 - kCacheBits));
}

}  // namespace

JsonStreamWriter::JsonStreamWriter(Sink sink, std::size_t flushBytes)
    : mSink(std::move(sink)), mFlushBytes(flushBytes), mFloats(std::size_t(1) << kCacheBits),
      mDoubles(std::size_t(1) << kCacheBits) {
    mOut.reserve(flushBytes + 4096);
}

void JsonStreamWriter::beginObject() { begin(false); }
void JsonStreamWriter::beginArray() { begin(true); }

void JsonStreamWriter::key(std::string_view name) {
    assert(!mFrames.empty() && !mFrames.back().array);
    mKey.clear();
    appendJsonString(mKey, name);
}

// A cached text goes out as one fixed-size copy: its 31 bytes and the size byte after them.
constexpr std::size_t kCachedCopy = 32;
static_assert(kJsonNumberChars >= kCachedCopy);

template <class Write>
char* JsonStreamWriter::cachedText(std::vector<CachedNumber>& cache, std::uint64_t bits, char* out, Write write) {
    static_assert(offsetof(CachedNumber, size) == offsetof(CachedNumber, text) + sizeof(CachedNumber::text) &&
                  sizeof(CachedNumber::text) + 1 == kCachedCopy);
    CachedNumber& cached = cache[cacheSlot(bits)];
    if (cached.size != 0 && cached.bits == bits) {
        std::memcpy(out, reinterpret_cast<const char*>(&cached) + offsetof(CachedNumber, text), kCachedCopy);
        return out + cached.size;
    }
    char* end = write(out);
    const auto size = static_cast<std::size_t>(end - out);
    if (size < sizeof cached.text) {
        // The whole text array at once (a fixed-size copy; `out` has kJsonNumberChars of room),
        // as the hit above copies it back.
        cached.bits = bits;
        cached.size = static_cast<std::uint8_t>(size);
        std::memcpy(cached.text, out, sizeof cached.text);
    }
    return end;
}

char* JsonStreamWriter::cachedDouble(char* out, double value) {
    return cachedText(mDoubles, std::bit_cast<std::uint64_t>(value), out,
                      [value](char* at) { return writeJsonDouble(at, value); });
}

char* JsonStreamWriter::cachedFloat(char* out, float value) {
    return cachedText(mFloats, std::bit_cast<std::uint32_t>(value), out,
                      [value](char* at) { return writeJsonFloat(at, value); });
}

template <class Write>
void JsonStreamWriter::numberValue(Write write) {
    const std::size_t at = openValue();
    char buffer[kJsonNumberChars];
    mOut.append(buffer, static_cast<std::size_t>(write(buffer) - buffer));
    closeValue(Kind::Scalar, false, at);
}

void JsonStreamWriter::number(double value) {
    numberValue([&](char* out) { return cachedDouble(out, value); });
}

void JsonStreamWriter::floatNumber(float value) {
    numberValue([&](char* out) { return cachedFloat(out, value); });
}

void JsonStreamWriter::integer(std::int64_t value) {
    const std::size_t at = openValue();
    appendInteger(mOut, value);
    closeValue(Kind::Scalar, false, at);
}

void JsonStreamWriter::unsignedInteger(std::uint64_t value) {
    const std::size_t at = openValue();
    appendInteger(mOut, value);
    closeValue(Kind::Scalar, false, at);
}

void JsonStreamWriter::boolean(bool value) { scalar(value ? "true" : "false"); }

void JsonStreamWriter::string(std::string_view text) {
    const std::size_t at = openValue();
    appendJsonString(mOut, text);
    closeValue(Kind::Scalar, false, at);
}

void JsonStreamWriter::value(const Json& value) {
    if (value.is_object()) {
        beginObject();
        for (const auto& [name, member] : value.items()) {
            key(name);
            this->value(member);
        }
        end();
    } else if (value.is_array()) {
        beginArray();
        for (const auto& element : value) this->value(element);
        end();
    } else {
        scalar(jsonScalarText(value));
    }
}

void JsonStreamWriter::position(const foresight::RVec3& position) {
    beginArray();
    number(static_cast<double>(position.x));
    number(static_cast<double>(position.y));
    number(static_cast<double>(position.z));
    end();
}

void JsonStreamWriter::vector(const foresight::Vec3& vector) {
    beginArray();
    floatNumber(vector.x);
    floatNumber(vector.y);
    floatNumber(vector.z);
    end();
}

void JsonStreamWriter::quaternion(const foresight::Quat& quaternion) {
    beginObject();
    key("w");
    floatNumber(quaternion.w);
    key("x");
    floatNumber(quaternion.x);
    key("y");
    floatNumber(quaternion.y);
    key("z");
    floatNumber(quaternion.z);
    end();
}

namespace {

/// Copies `text` to `out`; returns its end.
char* put(char* out, std::string_view text) {
    std::memcpy(out, text.data(), text.size());
    return out + text.size();
}

bool plainString(std::string_view text) {
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u > 0x7e || c == '"' || c == '\\') return false;
    }
    return true;
}

}  // namespace

void JsonStreamWriter::trajectoryPoint(float time, const foresight::RVec3& position, const foresight::Vec3& velocity,
                                       std::string_view event, const foresight::Vec3* normal) {
    // The point's own line when its array spans lines (nothing held): what end() keeps of the
    // value-by-value form when the point has at most kInlineNodes values (15 at most) and its
    // line fits in kLineWidth columns, checked below. Otherwise, value by value.
    constexpr std::size_t kMaxEvent = 32;
    if (holding() || mFrames.empty() || !mFrames.back().array || event.size() > kMaxEvent || !plainString(event)) {
        trajectoryPointValues(time, position, velocity, event, normal);
        return;
    }
    // 10 numbers, the keys and separators (under 100 bytes), the event.
    char line[10 * kJsonNumberChars + 128 + kMaxEvent];
    char* p = line;
    p = put(p, "{\"t\": ");
    p = cachedFloat(p, time);
    p = put(p, ", \"position\": [");
    p = cachedDouble(p, static_cast<double>(position.x));
    p = put(p, ", ");
    p = cachedDouble(p, static_cast<double>(position.y));
    p = put(p, ", ");
    p = cachedDouble(p, static_cast<double>(position.z));
    p = put(p, "], \"velocity\": [");
    p = cachedFloat(p, velocity.x);
    p = put(p, ", ");
    p = cachedFloat(p, velocity.y);
    p = put(p, ", ");
    p = cachedFloat(p, velocity.z);
    p = put(p, "], \"event\": \"");
    p = put(p, event);
    if (normal != nullptr) {
        p = put(p, "\", \"normal\": [");
        p = cachedFloat(p, normal->x);
        p = put(p, ", ");
        p = cachedFloat(p, normal->y);
        p = put(p, ", ");
        p = cachedFloat(p, normal->z);
        p = put(p, "]}");
    } else {
        p = put(p, "\"}");
    }
    const auto size = static_cast<std::size_t>(p - line);
    Frame& parent = mFrames.back();
    if (parent.indent + 2 + size > kLineWidth) {
        trajectoryPointValues(time, position, velocity, event, normal);  // laid out over lines
        return;
    }
    writePrefix(parent, {});
    mOut.append(line, size);
    maybeFlush();
}

void JsonStreamWriter::trajectoryPointValues(float time, const foresight::RVec3& position,
                                             const foresight::Vec3& velocity, std::string_view event,
                                             const foresight::Vec3* normal) {
    beginObject();
    key("t");
    floatNumber(time);
    key("position");
    this->position(position);
    key("velocity");
    vector(velocity);
    key("event");
    string(event);
    if (normal != nullptr) {
        key("normal");
        vector(*normal);
    }
    end();
}

void JsonStreamWriter::scalar(std::string_view text) {
    const std::size_t at = openValue();
    mOut += text;
    closeValue(Kind::Scalar, false, at);
}

void JsonStreamWriter::begin(bool array) {
    const std::size_t at = openValue();
    mOut += array ? '[' : '{';
    closeValue(Kind::Begin, array, at);
}

void JsonStreamWriter::writePrefix(Frame& parent, std::string_view key) {
    if (!parent.empty) mOut += ",\n";
    parent.empty = false;
    mOut.append(parent.indent + 2, ' ');
    if (!parent.array) {
        mOut += key;
        mOut += ": ";
    }
}

std::size_t JsonStreamWriter::openValue() {
    if (mFrames.empty()) return mOut.size();
    Frame& parent = mFrames.back();
    if (!holding()) {
        // The parent spans lines: the value's line starts here.
        writePrefix(parent, mKey);
        return mOut.size();
    }
    // Inside a held frame: its one-line form.
    if (!parent.empty) mOut += ", ";
    parent.empty = false;
    if (!parent.array) {
        mKeyAt = mOut.size() - mHeldStart;
        mOut += mKey;
        mOut += ": ";
    }
    return mOut.size();
}

void JsonStreamWriter::closeValue(Kind kind, bool array, std::size_t at) {
    if (!holding()) {
        mKey.clear();
        if (kind == Kind::Scalar) {
            if (mFrames.empty()) {
                mOut += '\n';  // a scalar document
            } else {
                maybeFlush();
            }
            return;
        }
        // An object or array whose parent spans lines (or the root): held until its layout is known.
        mHeldStart = at;
        mTokens.clear();
        Token token;
        token.kind = Kind::Begin;
        token.array = array;
        mTokens.push_back(token);
        Frame frame;
        frame.array = array;
        frame.indent = mFrames.empty() ? 0 : mFrames.back().indent + 2;
        mFrames.push_back(frame);
        return;
    }
    Token token;
    token.kind = kind;
    token.array = array;
    if (!mFrames.back().array) {
        token.key = static_cast<std::uint32_t>(mKeyAt);
        token.keySize = static_cast<std::uint32_t>(mKey.size());
    }
    mKey.clear();
    token.text = static_cast<std::uint32_t>(at - mHeldStart);
    token.textSize = static_cast<std::uint32_t>(mOut.size() - at);
    mTokens.push_back(token);
    for (std::size_t i = mFirstHeld; i < mFrames.size(); ++i) ++mFrames[i].nodes;
    if (kind == Kind::Begin) {
        Frame frame;
        frame.array = array;
        frame.indent = mFrames.back().indent + 2;
        frame.token = static_cast<std::uint32_t>(mTokens.size() - 1);
        mFrames.push_back(frame);
    }
    while (holding() && mFrames[mFirstHeld].nodes > kInlineNodes) spanLines(mFirstHeld);
}

void JsonStreamWriter::moveHeldText() {
    mText.assign(mOut, mHeldStart, std::string::npos);
    mOut.resize(mHeldStart);
}

void JsonStreamWriter::spanLines(std::size_t index) {
    // The outermost held frame has more values than fit on a line: it spans lines. Its prefix is
    // out already; write its opening and its finished members; the member still open (a held
    // frame) gets its prefix and stays held, its one-line form so far written again after it.
    moveHeldText();
    Frame& frame = mFrames[index];
    mOut += frame.array ? "[\n" : "{\n";
    frame.multiLine = true;
    frame.empty = true;
    const bool open = index + 1 < mFrames.size();
    const std::size_t stop = open ? mFrames[index + 1].token : mTokens.size();
    for (std::size_t i = 1; i < stop;) {
        const Token& member = mTokens[i];
        writePrefix(frame, textOf(member.key, member.keySize));
        layout(i, frame.indent + 2);
        i += member.kind == Kind::Begin ? member.length : 1;
    }
    mFirstHeld = index + 1;
    if (!open) {
        mTokens.clear();
        return;
    }
    Token& inner = mTokens[stop];
    writePrefix(frame, textOf(inner.key, inner.keySize));
    const std::uint32_t from = inner.text;
    inner.key = 0;
    inner.keySize = 0;  // written: not needed again
    mHeldStart = mOut.size();
    mOut.append(mText, from, std::string::npos);
    mTokens.erase(mTokens.begin(), mTokens.begin() + static_cast<std::ptrdiff_t>(stop));
    for (Token& token : mTokens) {
        token.text -= from;
        if (token.keySize != 0) token.key -= from;
    }
    for (std::size_t j = index + 1; j < mFrames.size(); ++j) mFrames[j].token -= static_cast<std::uint32_t>(stop);
}

void JsonStreamWriter::end() {
    assert(!mFrames.empty());
    const Frame frame = mFrames.back();
    mFrames.pop_back();
    if (frame.multiLine) {
        mOut += '\n';
        mOut.append(frame.indent, ' ');
        mOut += frame.array ? ']' : '}';
        mFirstHeld = mFrames.size();
    } else {
        mOut += frame.array ? ']' : '}';
        Token token;
        token.kind = Kind::End;
        token.array = frame.array;
        mTokens.push_back(token);
        Token& opening = mTokens[frame.token];
        opening.nodes = frame.nodes;
        opening.length = static_cast<std::uint32_t>(mTokens.size()) - frame.token;
        if (mFrames.size() == mFirstHeld) {
            // The outermost held value is complete. Its one-line form stands when formatJson would
            // print it on one line (empty, or few values within the width); else lay it out again.
            const std::size_t width = mOut.size() - mHeldStart;
            if (opening.length != 2 && (frame.nodes > kInlineNodes || frame.indent + width > kLineWidth)) {
                moveHeldText();
                layout(0, frame.indent);
            }
            mTokens.clear();
        }
    }
    if (mFrames.empty()) {
        mOut += '\n';
    } else {
        maybeFlush();
    }
}

void JsonStreamWriter::layout(std::size_t index, std::size_t indent) {
    // formatJson's writeValue over held tokens whose texts are in mText.
    const Token& token = mTokens[index];
    if (token.kind == Kind::Scalar || token.length == 2) {
        writeInline(index);
        return;
    }
    if (token.nodes <= kInlineNodes) {
        const std::size_t mark = mOut.size();
        writeInline(index);
        if (indent + (mOut.size() - mark) <= kLineWidth) return;
        mOut.resize(mark);
    }
    mOut += token.array ? "[\n" : "{\n";
    const std::size_t last = index + token.length - 1;
    for (std::size_t i = index + 1; i < last;) {
        const Token& member = mTokens[i];
        if (i != index + 1) mOut += ",\n";
        mOut.append(indent + 2, ' ');
        if (!token.array) {
            mOut += textOf(member.key, member.keySize);
            mOut += ": ";
        }
        layout(i, indent + 2);
        i += member.kind == Kind::Begin ? member.length : 1;
    }
    mOut += '\n';
    mOut.append(indent, ' ');
    mOut += token.array ? ']' : '}';
}

void JsonStreamWriter::writeInline(std::size_t index) {
    const Token& token = mTokens[index];
    if (token.kind == Kind::Scalar) {
        mOut += textOf(token.text, token.textSize);
        return;
    }
    mOut += token.array ? '[' : '{';
    const std::size_t last = index + token.length - 1;
    for (std::size_t i = index + 1; i < last;) {
        const Token& member = mTokens[i];
        if (i != index + 1) mOut += ", ";
        if (!token.array) {
            mOut += textOf(member.key, member.keySize);
            mOut += ": ";
        }
        writeInline(i);
        i += member.kind == Kind::Begin ? member.length : 1;
    }
    mOut += token.array ? ']' : '}';
}

void JsonStreamWriter::maybeFlush() {
    if (holding() || mOut.size() < mFlushBytes) return;
    if (!mFailed && !mSink(mOut)) mFailed = true;
    if (!mFailed) mWritten += mOut.size();
    mOut.clear();
}

bool JsonStreamWriter::finish() {
    assert(mFrames.empty());
    if (!mFailed && !mOut.empty()) {
        if (mSink(mOut)) {
            mWritten += mOut.size();
        } else {
            mFailed = true;
        }
    }
    mOut.clear();
    return !mFailed;
}

}  // namespace foresight_cli
