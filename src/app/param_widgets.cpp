// Parameter widgets driven by the table.
#include "param_widgets.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <imgui.h>
#include <string>

namespace clothtear::app {
namespace {

// A slider over many decades is useless when linear: switch to a logarithmic one.
bool wantsLog(double lo, double hi) { return (lo > 0 && hi / lo >= 100) || (lo == 0 && hi >= 1000); }

void tooltip(const ParamInfo& p, const Settings& s) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.f);
    ImGui::TextUnformatted(p.name);
    ImGui::Separator();
    ImGui::TextUnformatted(p.help);
    if (p.type == ParamType::Float || p.type == ParamType::Int) {
        ImGui::Text("Unit: %s", p.unit[0] ? p.unit : "(none)");
        ImGui::Text("Safe range: [%g, %g]", p.safeMin, p.safeMax);
        ImGui::Text("Hard range: [%g, %g]", p.hardMin, p.hardMax);
    }
    ImGui::Text("Now: %s", formatParamValue(s, p).c_str());
    if (p.rebuildsCloth) ImGui::TextColored(ImVec4(1.f, 0.8f, 0.3f, 1.f), "Changing it rebuilds the cloth.");
    ImGui::TextDisabled("Ctrl+click a slider to type a value.");
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

std::string shortLabel(const ParamInfo& p) {
    std::string_view n = p.name;
    if (const size_t dot = n.find('.'); dot != std::string_view::npos) n.remove_prefix(dot + 1);
    std::string label(n);
    std::replace(label.begin(), label.end(), '_', ' ');
    return label;
}

ParamEdit finish(bool changed, bool immediate) {
    if (immediate) return changed ? ParamEdit::Committed : ParamEdit::None;
    if (ImGui::IsItemDeactivatedAfterEdit()) return ParamEdit::Committed;
    return changed ? ParamEdit::Changed : ParamEdit::None;
}

} // namespace

ParamEdit paramWidget(Settings& s, const ParamInfo& p, bool unsafe) {
    ImGui::PushID(p.name);
    const std::string label = shortLabel(p);
    const double lo = unsafe ? p.hardMin : p.safeMin, hi = unsafe ? p.hardMax : p.safeMax;
    const double now = getParam(s, p);
    const bool outside = (p.type == ParamType::Float || p.type == ParamType::Int) && (now < p.safeMin || now > p.safeMax);
    ParamEdit edit = ParamEdit::None;
    ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | (wantsLog(lo, hi) ? ImGuiSliderFlags_Logarithmic : 0);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    switch (p.type) {
    case ParamType::Float: {
        float v = float(now);
        // The unit goes into a printf format: a '%' in it ("gf/cm per %", the kes law) is doubled.
        std::string unit = p.unit;
        for (size_t i = unit.find('%'); i != std::string::npos; i = unit.find('%', i + 2)) unit.insert(i, 1, '%');
        const std::string format = std::string("%.4g") + (unit.empty() ? "" : " ") + unit;
        const bool changed = ImGui::SliderFloat(label.c_str(), &v, float(lo), float(hi), format.c_str(), flags);
        if (changed) setParamUnchecked(s, p, v);
        edit = finish(changed, false);
        break;
    }
    case ParamType::Int: {
        int v = int(now);
        const bool changed = ImGui::SliderInt(label.c_str(), &v, int(lo), int(hi), "%d", flags);
        if (changed) setParamUnchecked(s, p, v);
        edit = finish(changed, false);
        break;
    }
    case ParamType::Bool: {
        bool v = now != 0.0;
        const bool changed = ImGui::Checkbox(label.c_str(), &v);
        if (changed) setParamUnchecked(s, p, v ? 1.0 : 0.0);
        edit = finish(changed, true);
        break;
    }
    case ParamType::Enum: {
        int v = int(now), count = 0;
        while (p.enumNames[count]) ++count;
        const char* preview = v >= 0 && v < count ? p.enumNames[v] : "?";
        bool changed = false;
        if (ImGui::BeginCombo(label.c_str(), preview)) {
            for (int i = 0; i < count; ++i)
                if (ImGui::Selectable(p.enumNames[i], i == v) && i != v) v = i, changed = true;
            ImGui::EndCombo();
        }
        if (changed) setParamUnchecked(s, p, v);
        edit = finish(changed, true);
        break;
    }
    }
    tooltip(p, s);
    if (outside) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1.f, 0.55f, 0.2f, 1.f), "(!)");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Outside the safe range: the cloth may become unstable.");
    }
    ImGui::PopID();
    return edit;
}

bool paramWidgets(Settings& s, std::string_view prefix, bool unsafe) {
    bool rebuild = false;
    for (const ParamInfo& p : allParams())
        if (std::string_view(p.name).starts_with(prefix))
            rebuild |= paramWidget(s, p, unsafe) == ParamEdit::Committed && p.rebuildsCloth;
    return rebuild;
}

bool parameterGroups(Settings& s, bool unsafe) {
    bool rebuild = false;
    std::string_view group;
    bool open = false;
    for (const ParamInfo& p : allParams()) {
        const std::string_view name = p.name;
        const std::string_view g = name.substr(0, name.find('.'));
        if (g != group) {
            if (open) ImGui::TreePop();
            group = g;
            std::string title(g);
            title[0] = char(std::toupper(static_cast<unsigned char>(title[0])));
            // The whole row opens the group, not only its label (people click beside short names).
            open = ImGui::TreeNodeEx(title.c_str(), ImGuiTreeNodeFlags_SpanAvailWidth);
        }
        if (open) rebuild |= paramWidget(s, p, unsafe) == ParamEdit::Committed && p.rebuildsCloth;
    }
    if (open) ImGui::TreePop();
    return rebuild;
}

} // namespace clothtear::app
