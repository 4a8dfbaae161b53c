#include "cablefit/app/output/solution_json.h"

#include "cablefit/formats/json_writer.h"

namespace cablefit::addin {

std::string SolutionJsonText(const std::string& case_name, const RodSpec& spec,
                             const SimulationResult& r, const json::Json& provenance) {
  const RodSolution& sol = r.solution;
  const StaticsSummary& sum = sol.summary;
  json::JsonWriter w;
  w.BeginObject();
  w.Key("format").String("cablefit-solution/1");
  w.Key("case").String(case_name);
  w.Key("length").Number(spec.length);
  w.Key("reactions").BeginArray();
  for (size_t k = 0; k < sol.reactions.size(); ++k) {
    const SupportReaction& re = sol.reactions[k];
    w.BeginObject();
    w.Key("index").Integer(static_cast<long long>(k));
    w.Key("kind").String(ToString(re.kind));
    w.Key("s").Number(re.s);
    w.Key("force").Numbers(re.force);
    w.Key("moment").Numbers(re.moment);
    w.EndObject();
  }
  w.EndArray();
  w.Key("summary").BeginObject();
  w.Key("termination").String(ToString(sum.termination));
  w.Key("converged").Bool(r.converged);
  w.Key("message").String(sum.message);
  w.Key("iterations").Integer(r.newton_iterations);
  w.Key("continuation_steps").Integer(sum.continuation_steps);
  w.Key("residual").BeginObject();
  w.Key("gradient").Number(sum.gradient_norm);
  w.Key("constraint").Number(sum.constraint_norm);
  w.EndObject();
  w.Key("energy").Number(sum.final_energy);
  w.Key("elastic_energy").Number(sol.elastic_energy);
  w.Key("stable").Bool(sum.stable);
  w.Key("unstable_directions").Integer(sum.negative_directions);
  w.Key("elements").Integer(r.level_elements.empty() ? 0 : r.level_elements.back());
  w.Key("levels").Integers(r.level_elements);
  w.Key("estimated_error").Number(r.estimated_error);
  w.Key("accuracy_met").Bool(r.accuracy_met);
  w.Key("seconds").Number(r.seconds);
  w.EndObject();
  w.Key("twist_angle").Number(sol.twist_angle);
  // Profiles of the finest level: frames and internal force at element midpoints, internal
  // moment at the frame-sample edges.
  w.Key("frames").BeginArray();
  for (size_t i = 0; i < sol.frames.size(); ++i) {
    const int c = static_cast<int>(i);
    w.BeginObject();
    w.Key("s").Number(sol.frame_s[c]);
    w.Key("d1").Numbers(sol.frames[i].d1);
    w.Key("d2").Numbers(sol.frames[i].d2);
    w.Key("d3").Numbers(sol.frames[i].d3);
    w.Key("force").Numbers(sol.internal_force.col(c));
    w.EndObject();
  }
  w.EndArray();
  w.Key("moments").BeginArray();
  for (int e = 0; e < sol.internal_moment.cols(); ++e) {
    w.BeginObject();
    w.Key("s").Number(sol.moment_s[e]);
    w.Key("moment").Numbers(sol.internal_moment.col(e));
    w.EndObject();
  }
  w.EndArray();
  w.Key("provenance").Tree(provenance);
  w.EndObject();
  return w.Finish();
}

}  // namespace cablefit::addin
