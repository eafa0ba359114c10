// `woven pattern`: print the top-yarn map of a weave as MODEL.md draws it.
#include <iostream>
#include <stdexcept>

#include "commands.h"
#include "weave_pattern.h"

namespace woven {

void addPatternCommand(CLI::App& app) {
    struct Options {
        std::vector<int> pattern{1, 1, 1};
        std::vector<int> size;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("pattern", "Print the top-yarn map of a weave ('-' weft, '|' warp)");
    cmd->add_option("--pattern", opts->pattern, "I,J,K: I weft, J warp elements per row, shift K per row")
        ->delimiter(',')->expected(3);
    cmd->add_option("--size", opts->size, "W,H: columns and rows to print (default: one repeat)")
        ->delimiter(',')->expected(2);
    cmd->callback([opts] {
        const auto& p = opts->pattern;
        if (p[0] < 0 || p[1] < 0 || p[0] + p[1] < 1 || p[0] + p[1] > 1024)
            throw std::invalid_argument("--pattern: need I, J >= 0 and 1 <= I + J <= 1024");
        const WeavePattern weave = WeavePattern::regular(p[0], p[1], p[2]);
        int w = weave.width(), h = weave.height();
        if (!opts->size.empty()) {
            w = opts->size[0];
            h = opts->size[1];
            if (w < 1 || h < 1 || w > 100000 || h > 100000)
                throw std::invalid_argument("--size: W and H must be between 1 and 100000");
        }
        std::cout << weave.draw(w, h);
    });
}

}  // namespace woven
