// Every command's option parsing on any command line (the bytes' words between NUL bytes): woven's
// own CLI (commands.h) parses, checks and cross-checks the options as `woven` does, and stops
// where a command would start its work, so nothing is read, rendered or written; a refusal is
// then put into words as woven's main() does (parse_errors.h), with the output discarded.
#include <cstdlib>
#include <iostream>
#include <streambuf>

#include "commands.h"
#include "fuzz_input.h"
#include "parse_errors.h"

namespace {

// Thrown where the command's action would begin: every option has been parsed and checked.
struct Parsed {};

// Swallows what CLI11 and the messages print (help pages, errors) unless refusals are shown.
class Silence {
public:
    Silence() : quiet_(std::getenv("WOVEN_FUZZ_SHOW_ERRORS") == nullptr) {
        if (quiet_) out_ = std::cout.rdbuf(&none_), err_ = std::cerr.rdbuf(&none_);
    }
    ~Silence() {
        if (quiet_) std::cout.rdbuf(out_), std::cerr.rdbuf(err_);
    }

private:
    struct Discard : std::streambuf {
        int overflow(int c) override { return c; }
    } none_;
    bool quiet_;
    std::streambuf *out_ = nullptr, *err_ = nullptr;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> words = woven::fuzz::arguments(data, size);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    CLI::App app{"woven"};
    woven::addCommands(app);
    // The root's own callback runs after every command's parsing and checks, before any action.
    app.parse_complete_callback([] { throw Parsed{}; });
    const Silence silence;
    try {
        app.parse(int(argv.size()), argv.data());
    } catch (const Parsed&) {
    } catch (const CLI::ParseError& e) {
        woven::reportParseError(app, e, int(argv.size()), argv.data());
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        woven::fuzz::showRefusal(e);
    }
    return 0;
}
