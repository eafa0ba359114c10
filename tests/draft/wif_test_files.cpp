#include "wif_test_files.h"

#include <fstream>
#include <stdexcept>

#include "draft_tile.h"
#include "temp_dir.h"
#include "wif_reader.h"

namespace woven::test {

std::string twillWif() {
    return R"([WIF]
Version=1.1
Date=April 20, 1997
Developers=wif@mhsoft.com
Source Program=woven tests

[CONTENTS]
COLOR PALETTE=true
WEAVING=true
WARP=true
WEFT=true
COLOR TABLE=true
THREADING=true
TIEUP=true
TREADLING=true

[COLOR PALETTE]
Entries=2
Form=RGB
Range=0,255

[WEAVING]
Shafts=4
Treadles=4
Rising Shed=true

[WARP]
Threads=8
Color=1

[WEFT]
Threads=8
Color=2

[COLOR TABLE]
1=255,255,255
2=0,0,0

[THREADING]
1=1
2=2
3=3
4=4
5=1
6=2
7=3
8=4

[TIEUP]
1=1,2
2=2,3
3=3,4
4=4,1

[TREADLING]
1=1
2=2
3=3
4=4
5=1
6=2
7=3
8=4
)";
}

std::vector<std::string> twillMap() {
    return {"||--||--", "-||--||-", "--||--||", "|--||--|", "||--||--", "-||--||-", "--||--||", "|--||--|"};
}

std::string plainLiftplanWif() {
    return R"([WIF]
Version=1.1

[WEAVING]
Shafts=2
Treadles=0

[WARP]
Threads=4

[WEFT]
Threads=4

[THREADING]
1=1
2=2
3=1
4=2

[LIFTPLAN]
1=1
2=2
3=1
4=2
)";
}

std::vector<std::string> plainMap() { return {"|-|-", "-|-|", "|-|-", "-|-|"}; }

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    size_t at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test text lacks '" + from + "'");
    for (; at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
    return text;
}

Draft readText(const std::string& text, std::vector<std::string>& warnings, const std::string& fileName) {
    const TempDir dir;
    const std::string path = dir.file(fileName);
    std::ofstream(path, std::ios::binary) << text;
    return readWif(path, warnings);
}

std::vector<std::string> mapOf(const Draft& draft) { return draftTile(draft, "test draft").rows; }

}  // namespace woven::test
