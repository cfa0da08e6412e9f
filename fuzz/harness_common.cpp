// The list of harnesses and the check every refusal message must pass.
#include "harness.h"

namespace clothtear::fuzz {

std::span<const Target> targets() {
    static const Target kTargets[] = {
        {"obj", fuzzObj},
        {"set", fuzzSet},
        {"config", fuzzConfig},
        {"script", fuzzScript},
        {"world", fuzzWorld},
    };
    return kTargets;
}

std::string checkMessage(const std::string& message, const std::string& source) {
    if (message.empty())
        return "refused without a message";
    if (message.rfind(source, 0) != 0)
        return "message does not start with '" + source + "': " + message;
    if (message.find('\n') != std::string::npos)
        return "message is more than one line: " + message;
    return {};
}

} // namespace clothtear::fuzz
