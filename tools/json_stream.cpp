#include "json_stream.h"

#include <cassert>
#include <charconv>
#include <cmath>
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
    // jsonDouble: integral values below 2^53 become integers (-0 prints as 0); the rest are
    // printed by nlohmann::json's own double conversion (Grisu2, with its exponent format), the
    // very function its serializer calls, so that the bytes stay those formatJson prints. Grisu2
    // is not always the shortest decimal (std::to_chars differs in about one value in a thousand),
    // so std::to_chars cannot stand in for it.
    if (!std::isfinite(value)) {
        out += "null";  // what nlohmann prints; the CLI checks results for finiteness first
        return;
    }
    if (value == std::trunc(value) && std::fabs(value) < 9007199254740992.0) {
        appendInteger(out, static_cast<std::int64_t>(value));
        return;
    }
    char buffer[64];
    const char* end = nlohmann::detail::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, static_cast<std::size_t>(end - buffer));
}

void appendJsonFloat(std::string& out, float value) {
    // jsonFloat: the double nearest to the float's shortest round-trip decimal.
    char buffer[64];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, value);
    double parsed = static_cast<double>(value);
    if (written.ec == std::errc()) {
        double fromText = 0;
        const auto read = std::from_chars(buffer, written.ptr, fromText);
        if (read.ec == std::errc()) parsed = fromText;
    }
    appendJsonDouble(out, parsed);
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

JsonStreamWriter::JsonStreamWriter(Sink sink, std::size_t flushBytes)
    : mSink(std::move(sink)), mFlushBytes(flushBytes) {
    mOut.reserve(flushBytes + 4096);
}

void JsonStreamWriter::beginObject() { begin(false); }
void JsonStreamWriter::beginArray() { begin(true); }

void JsonStreamWriter::key(std::string_view name) {
    assert(!mFrames.empty() && !mFrames.back().array);
    mKey.clear();
    appendJsonString(mKey, name);
}

void JsonStreamWriter::number(double value) {
    mScratch.clear();
    appendJsonDouble(mScratch, value);
    scalar(mScratch);
}

void JsonStreamWriter::floatNumber(float value) {
    mScratch.clear();
    appendJsonFloat(mScratch, value);
    scalar(mScratch);
}

void JsonStreamWriter::integer(std::int64_t value) {
    mScratch.clear();
    appendInteger(mScratch, value);
    scalar(mScratch);
}

void JsonStreamWriter::unsignedInteger(std::uint64_t value) {
    mScratch.clear();
    appendInteger(mScratch, value);
    scalar(mScratch);
}

void JsonStreamWriter::boolean(bool value) { scalar(value ? "true" : "false"); }

void JsonStreamWriter::string(std::string_view text) {
    mScratch.clear();
    appendJsonString(mScratch, text);
    scalar(mScratch);
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
        scalar(value.dump(-1, ' ', false, Json::error_handler_t::replace));
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

void JsonStreamWriter::scalar(std::string_view text) {
    if (startValue(Kind::Scalar, false, text) && mFrames.empty()) endDocument();
}

void JsonStreamWriter::begin(bool array) { startValue(Kind::Begin, array, {}); }

std::uint32_t JsonStreamWriter::keep(std::string_view text) {
    const auto at = static_cast<std::uint32_t>(mText.size());
    mText += text;
    return at;
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

bool JsonStreamWriter::startValue(Kind kind, bool array, std::string_view text) {
    if (mFirstHeld == mFrames.size()) {
        // The parent spans lines (or this is the root): the prefix goes out now, a scalar too; an
        // object or array is held until its layout is known.
        std::uint32_t indent = 0;
        if (!mFrames.empty()) {
            writePrefix(mFrames.back(), mKey);
            indent = mFrames.back().indent + 2;
        }
        mKey.clear();
        if (kind == Kind::Scalar) {
            mOut += text;
            maybeFlush();
            return true;
        }
        mTokens.clear();
        mText.clear();
        Token token;
        token.kind = Kind::Begin;
        token.array = array;
        mTokens.push_back(token);
        Frame frame;
        frame.array = array;
        frame.indent = indent;
        frame.token = 0;
        mFrames.push_back(frame);
        return false;
    }
    Token token;
    token.kind = kind;
    token.array = array;
    if (!mFrames.back().array) {
        token.key = keep(mKey);
        token.keySize = static_cast<std::uint32_t>(mKey.size());
    }
    mKey.clear();
    if (kind == Kind::Scalar) {
        token.text = keep(text);
        token.textSize = static_cast<std::uint32_t>(text.size());
    }
    mTokens.push_back(token);
    for (std::size_t i = mFirstHeld; i < mFrames.size(); ++i) ++mFrames[i].nodes;
    if (kind == Kind::Begin) {
        Frame frame;
        frame.array = array;
        frame.indent = mFrames.back().indent + 2;
        frame.token = static_cast<std::uint32_t>(mTokens.size() - 1);
        mFrames.push_back(frame);
    }
    while (mFirstHeld < mFrames.size() && mFrames[mFirstHeld].nodes > kInlineNodes) spanLines(mFirstHeld);
    return false;
}

void JsonStreamWriter::spanLines(std::size_t index) {
    // The outermost held frame has more values than fit on a line: it spans lines. Its prefix is
    // out already; write its opening and its finished members; the member still open (a held
    // frame) gets its prefix and stays held.
    Frame& frame = mFrames[index];
    mOut += frame.array ? "[\n" : "{\n";
    frame.multiLine = true;
    frame.empty = true;
    const bool open = index + 1 < mFrames.size();
    const std::size_t stop = open ? mFrames[index + 1].token : mTokens.size();
    for (std::size_t i = 1; i < stop;) {
        const Token& member = mTokens[i];
        writePrefix(frame, std::string_view(mText).substr(member.key, member.keySize));
        layout(i, frame.indent + 2);
        i += member.kind == Kind::Begin ? member.length : 1;
    }
    mFirstHeld = index + 1;
    if (open) {
        const Token& member = mTokens[stop];
        writePrefix(frame, std::string_view(mText).substr(member.key, member.keySize));
        mTokens.erase(mTokens.begin(), mTokens.begin() + static_cast<std::ptrdiff_t>(stop));
        for (std::size_t j = index + 1; j < mFrames.size(); ++j) mFrames[j].token -= static_cast<std::uint32_t>(stop);
    } else {
        mTokens.clear();
        mText.clear();
    }
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
        Token token;
        token.kind = Kind::End;
        token.array = frame.array;
        mTokens.push_back(token);
        Token& opening = mTokens[frame.token];
        opening.nodes = frame.nodes;
        opening.length = static_cast<std::uint32_t>(mTokens.size()) - frame.token;
        if (mFrames.size() == mFirstHeld) {
            // The outermost held value is complete: lay it out as formatJson would.
            layout(0, frame.indent);
            mTokens.clear();
            mText.clear();
        }
    }
    if (mFrames.empty()) {
        endDocument();
    } else {
        maybeFlush();
    }
}

void JsonStreamWriter::layout(std::size_t index, std::size_t indent) {
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
            mOut.append(mText, member.key, member.keySize);
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
        mOut.append(mText, token.text, token.textSize);
        return;
    }
    mOut += token.array ? '[' : '{';
    const std::size_t last = index + token.length - 1;
    for (std::size_t i = index + 1; i < last;) {
        const Token& member = mTokens[i];
        if (i != index + 1) mOut += ", ";
        if (!token.array) {
            mOut.append(mText, member.key, member.keySize);
            mOut += ": ";
        }
        writeInline(i);
        i += member.kind == Kind::Begin ? member.length : 1;
    }
    mOut += token.array ? ']' : '}';
}

void JsonStreamWriter::endDocument() { mOut += '\n'; }

void JsonStreamWriter::maybeFlush() {
    if (mOut.size() < mFlushBytes) return;
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
