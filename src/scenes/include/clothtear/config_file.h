// Config files (`clothtear --config FILE`): a scene and parameters as text, read through the same
// parameter table as --set (params.h), so a file can hold any row of --list-params.
//
//   # the tension experiment with a pre-cut slit
//   scene = tension               optional: a scene of --list-scenes, or obj:PATH
//   tension.notch = on
//   tear.threshold = 0.3          any parameter; same parsing and ranges as --set
//
// One `key = value` per line; '#' starts a comment anywhere on a line; blank lines are ignored. A later
// line for the same key wins, and --set on the command line wins over the file. Every line is checked
// when the file is read; errors read "FILE:LINE: what was wrong".
#pragma once
#include "clothtear/types.h"

#include <string>
#include <string_view>
#include <vector>

namespace clothtear {

struct ConfigFile {
    std::string scene;                    // "" when the file names none
    std::vector<std::string> assignments; // "key=value", in file order, each one already checked
};

// Parses config text; `source` names it in messages (the file's path).
Result<ConfigFile> parseConfig(std::string_view text, const std::string& source);
// Reads and parses a file: missing, unreadable, over 1 MiB or binary files are errors naming it.
Result<ConfigFile> loadConfig(const std::string& path);

} // namespace clothtear
