#include "cablefit/app/output/solution_json.h"

namespace cablefit::addin {
using namespace cablefit::json;

json::Json SolutionToJson(const std::string& case_name, const RodSpec& spec, const SimulationResult& r) {
  const RodSolution& sol = r.solution;
  const StaticsSummary& sum = sol.summary;
  Json j;
  j["format"] = "cablefit-solution/1";
  j["case"] = case_name;
  j["length"] = spec.length;
  Json reactions = Json::array();
  for (size_t k = 0; k < sol.reactions.size(); ++k) {
    const SupportReaction& re = sol.reactions[k];
    reactions.push_back({{"index", k},
                         {"kind", ToString(re.kind)},
                         {"s", re.s},
                         {"force", ToJson(re.force)},
                         {"moment", ToJson(re.moment)}});
  }
  j["reactions"] = reactions;
  j["summary"] = {{"termination", ToString(sum.termination)},
                  {"converged", r.converged},
                  {"message", sum.message},
                  {"iterations", r.newton_iterations},
                  {"continuation_steps", sum.continuation_steps},
                  {"residual", {{"gradient", NumberOrNull(sum.gradient_norm)},
                                {"constraint", NumberOrNull(sum.constraint_norm)}}},
                  {"energy", NumberOrNull(sum.final_energy)},
                  {"elastic_energy", NumberOrNull(sol.elastic_energy)},
                  {"stable", sum.stable},
                  {"unstable_directions", sum.negative_directions},
                  {"elements", r.level_elements.empty() ? 0 : r.level_elements.back()},
                  {"levels", r.level_elements},
                  {"estimated_error", NumberOrNull(r.estimated_error)},
                  {"accuracy_met", r.accuracy_met},
                  {"seconds", r.seconds}};
  j["twist_angle"] = NumberOrNull(sol.twist_angle);
  // Profiles of the finest level: frames and internal force at element midpoints, internal
  // moment at the frame-sample edges.
  Json frames = Json::array();
  for (size_t i = 0; i < sol.frames.size(); ++i)
    frames.push_back({{"s", sol.frame_s[static_cast<int>(i)]},
                      {"d1", ToJson(sol.frames[i].d1)},
                      {"d2", ToJson(sol.frames[i].d2)},
                      {"d3", ToJson(sol.frames[i].d3)},
                      {"force", ToJson(sol.internal_force.col(static_cast<int>(i)))}});
  j["frames"] = frames;
  Json moments = Json::array();
  for (int e = 0; e < sol.internal_moment.cols(); ++e)
    moments.push_back({{"s", sol.moment_s[e]}, {"moment", ToJson(sol.internal_moment.col(e))}});
  j["moments"] = moments;
  return j;
}

}  // namespace cablefit::addin
