// Input script harness: an accepted script writes out and reads back to the same events.
#include "harness.h"

#include "input_script.h"

namespace clothtear::fuzz {

std::string fuzzScript(std::string_view bytes) {
    const std::string source = "fuzz.txt";
    const Result<app::InputScript> r = app::parseInputScript(bytes, source);
    if (!r.ok())
        return checkMessage(r.error, source);
    for (size_t i = 1; i < r.value.events.size(); ++i)
        if (r.value.events[i].frame < r.value.events[i - 1].frame)
            return "accepted decreasing frames";
    const std::string text = app::formatInputScript(r.value);
    const Result<app::InputScript> again = app::parseInputScript(text, "written");
    if (!again.ok())
        return "the written script does not read back: " + again.error;
    if (again.value.events != r.value.events)
        return "the written script reads back to other events:\n" + text;
    return {};
}

} // namespace clothtear::fuzz
