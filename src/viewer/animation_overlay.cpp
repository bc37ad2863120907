#include "viewer/animation_overlay.h"

#include <imgui.h>

namespace wf {

void animationSection(const AnimationFacts& facts, AnimationActions& actions) {
    if (!facts.animated || !ImGui::CollapsingHeader("Animation", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    actions.togglePlay = ImGui::Button(facts.playing ? "Pause (T)" : "Play (T)");
    ImGui::SameLine();
    ImGui::Text("frame %u at %.0f fps", facts.frame, facts.fps);
    float time = float(facts.time);
    if (ImGui::SliderFloat("--time (s)", &time, 0.0f, float(facts.end), "%.3f")) {
        actions.seek = true;
        actions.seekTime = time;
    }
}

} // namespace wf
