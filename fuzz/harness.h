// Fuzz harnesses: one function per input format of clothtear. Each takes arbitrary bytes, feeds them
// to the parser the program uses and checks what must hold whatever the bytes are:
//   - the input is accepted, and then what was parsed is consistent (a mesh builds a valid cloth, a
//     value is in its range and reads back the same, a script writes and re-reads identically), or
//   - it is refused with one line that starts with the file name ("fuzz.obj:12: ...").
// A harness returns "" when that held, else what broke. The libFuzzer targets (fuzz_main.cpp) abort
// on a non-empty answer; tests/test_fuzz_corpus.cpp replays the seed corpora and every regression
// input through the same functions in ordinary builds.
#pragma once
#include <span>
#include <string>
#include <string_view>

namespace clothtear::fuzz {

std::string fuzzObj(std::string_view bytes);    // OBJ importer (parseObj), then buildCloth and tears
std::string fuzzSet(std::string_view bytes);    // one --set key=value (applyAssignment)
std::string fuzzConfig(std::string_view bytes); // a --config file (parseConfig)
std::string fuzzScript(std::string_view bytes); // an input script (parseInputScript)
std::string fuzzWorld(std::string_view bytes);  // a world file (parseWorld), then a save and a frame

struct Target {
    const char* name; // fuzz/corpus/<name>, fuzz/regressions/<name>, fuzz_<name>
    std::string (*run)(std::string_view bytes);
};
std::span<const Target> targets();

// "" when `message` is one non-empty line starting with `source`, else what is wrong with it.
std::string checkMessage(const std::string& message, const std::string& source);

} // namespace clothtear::fuzz
