// docs/SCENE_FORMAT.md's table of the woven parameters is wovenParamTable() itself: every key, its
// type, range, default and meaning as the table says them, in the table's order. A key added,
// renamed or re-ranged in code and not in the docs (or the other way round) fails here, and the
// failure prints the table to paste.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "woven_params.h"

namespace woven {
namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

const char* typeName(ParamType t) {
    switch (t) {
        case ParamType::Float: return "number";
        case ParamType::Int: return "integer";
        case ParamType::Vec2: return "2 numbers";
        case ParamType::Vec3: return "RGB or one number";
        case ParamType::IVec3: return "3 integers";
        case ParamType::Rows: return "list of strings";
        case ParamType::Vec3List: return "list of RGB";
        case ParamType::IntList: return "list of integers";
        case ParamType::FloatList: return "list of numbers";
        case ParamType::YarnList: return "list of objects";
    }
    return "";
}

// The default of an entry, read from a default WovenParams through its offset.
std::string defaultValue(const ParamInfo& info) {
    static const WovenParams defaults;
    const char* field = reinterpret_cast<const char*>(&defaults) + info.offset;
    const auto list = [](const float* v, int n) {
        std::string text = "[";
        for (int i = 0; i < n; ++i) text += (i ? ", " : "") + number(v[i]);
        return text + "]";
    };
    switch (info.type) {
        case ParamType::Float: return number(*reinterpret_cast<const float*>(field));
        case ParamType::Int: return std::to_string(*reinterpret_cast<const int*>(field));
        case ParamType::Vec2: return list(reinterpret_cast<const float*>(field), 2);
        case ParamType::Vec3: return list(reinterpret_cast<const float*>(field), 3);
        case ParamType::IVec3: {
            const int* v = reinterpret_cast<const int*>(field);
            return "[" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + "]";
        }
        default: return "none";
    }
}

std::string range(const ParamInfo& info) {
    if (info.type == ParamType::Rows || info.type == ParamType::YarnList) return "";
    return number(info.min) + " to " + number(info.max);
}

std::string generatedTable() {
    std::string table = "| key | type | range | default | meaning |\n|---|---|---|---|---|\n";
    for (const ParamInfo& info : wovenParamTable()) {
        std::string meaning = info.description;
        if (info.fallback) meaning += std::string(" (absent: as `") + info.fallback + "`)";
        table += std::string("| `") + info.name + "` | " + typeName(info.type) + " | " + range(info) + " | " +
                 defaultValue(info) + " | " + meaning + " |\n";
    }
    return table;
}

TEST(ParamDocs, SceneFormatTableIsTheParameterTable) {
    std::ifstream in(std::string(WOVEN_SOURCE_DIR) + "/docs/SCENE_FORMAT.md");
    ASSERT_TRUE(in) << "docs/SCENE_FORMAT.md not found";
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    const std::string begin = "<!-- the woven parameters: generated from wovenParamTable() -->\n";
    const std::string end = "<!-- end of the woven parameters -->";
    const size_t from = doc.find(begin), to = doc.find(end);
    ASSERT_NE(from, std::string::npos) << "the table's opening marker is missing";
    ASSERT_NE(to, std::string::npos) << "the table's closing marker is missing";
    const std::string documented = doc.substr(from + begin.size(), to - from - begin.size());
    EXPECT_EQ(documented, generatedTable()) << "docs/SCENE_FORMAT.md's table differs from wovenParamTable(): "
                                               "replace it with\n" << generatedTable();
}

TEST(ParamDocs, EveryEntryIsDescribed) {
    for (const ParamInfo& info : wovenParamTable()) {
        ASSERT_NE(info.description, nullptr) << info.name;
        EXPECT_GT(std::string(info.description).size(), 10u) << info.name;
        EXPECT_EQ(std::string(info.description).find('|'), std::string::npos) << info.name << ": '|' breaks the table";
    }
}

}  // namespace
}  // namespace woven
