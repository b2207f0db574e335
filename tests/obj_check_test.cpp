// checkObjText: what tinyobjloader reads leniently is refused with the line; valid OBJ passes.
#include <foresight/obj_check.h>

#include <gtest/gtest.h>

#include <string>

using foresight::checkObjText;

namespace {

std::string refusal(const std::string& text) {
    std::string reason;
    return checkObjText(text, reason) ? std::string("accepted") : reason;
}

}  // namespace

TEST(ObjCheck, AcceptsTheForms) {
    const char* valid[] = {
        "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n",
        "v 0 0 0 1\nv 1 0 0 1.0\nv 0 0 1 1\nf 1 2 3\n",            // w
        "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 0 1 0 0 1\nf 1 2 3\n",  // vertex colours
        "v -1.5e+2 +.5 3.\nv 1E-3 0 0\nv 0 0 1\nf -3 -2 -1\n",     // signs, exponents, relative
        "v 0 0 0\r\nv 1 0 0\r\nv 0 0 1\r\nvn 0 1 0\r\nvt 0 0\r\nf 1/1/1 2//1 3/1\r\n",
        "# comment\n\n  v 0 0 0 # trailing\n\tv 1 0 0\nv 0 0 1\nf 1 2 3 # face\ng group\nusemtl x\nl 1 2\n",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",  // polygons
        "",                                                 // no faces: the loaders say so
    };
    for (const char* text : valid) EXPECT_EQ(refusal(text), "accepted") << text;
}

TEST(ObjCheck, RefusesWhatALenientReaderMisreads) {
    const std::string head = "v 0 0 0\nv 1 0 0\n";
    struct Case {
        std::string text, expected;
    };
    const Case cases[] = {
        {head + "v 0 0 nan\n", "line 3: vertex value \"nan\" is not a finite decimal number"},
        {head + "v 0 0 -inf\n", "\"-inf\""},
        {head + "v 0 0 abc\n", "\"abc\""},
        {head + "v 0 0 +\n", "\"+\""},
        {head + "v 0 0 .\n", "\".\""},
        {head + "v 0 0 1e\n", "\"1e\""},
        {head + "v 0 0 0x10\n", "\"0x10\""},
        {head + "v 0 0 1,5\n", "\"1,5\""},
        {head + "v 0 0 1..2\n", "\"1..2\""},
        {head + "v 0 0 1e39\n", "within float range"},
        {head + "v 1 0\n", "line 3: a vertex has 2 numbers"},
        {head + "v 1 0 0 1 1\n", "a vertex has 5 numbers"},
        {head + "v 0 0 1\nf 1 2 3.7\n", "line 4: face corner \"3.7\""},
        {head + "v 0 0 1\nf 1 2 4294967299\n", "face corner \"4294967299\""},
        {head + "v 0 0 1\nf 1 2 0\n", "face corner \"0\""},
        {head + "v 0 0 1\nf 1 2 3/\n", "face corner \"3/\""},
        {head + "v 0 0 1\nf 1 2 3/1/2/4\n", "face corner \"3/1/2/4\""},
        {head + "v 0 0 1\nf 1 2 3/x\n", "face corner \"3/x\""},
        {head + "v 0 0 1\nf 1 2\n", "line 4: a face has 2 corner(s)"},
        {head + "v 0 0 1\nf 1 2 -4\n", "counts back past the first vertex, out of range (3 read so far)"},
        {head + "v 0 0 1\nf 1 2 9\n", "line 4: a face refers to vertex 9, out of range (the file has 3 vertices)"},
        {head + "v 0 0 1\nf 1 2 3\n" + std::string(1, '\0') + "junk", "line 5: a NUL byte"},
        {head + "v 0 0 \x1b[31m\n", "\"\\x1b[31m\""},  // escape codes are quoted, never printed raw
    };
    for (const Case& c : cases) {
        const std::string reason = refusal(c.text);
        EXPECT_NE(reason.find(c.expected), std::string::npos) << c.text << " -> " << reason;
        EXPECT_EQ(reason.find('\n'), std::string::npos) << reason;
    }
}
