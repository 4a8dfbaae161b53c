// `cablefit section SECTION.json [--out FILE]`: composite cross-section stiffness (cli-v1).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <numbers>
#include <iostream>
#include <string>
#include <vector>

#include "cablefit/cli/commands.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/app/base/provenance.h"
#include "cablefit/app/config/section_json.h"

namespace cablefit::addin {
namespace {

// The figures an engineer copies into a harness.json, with units; the JSON has the rest.
std::string SectionSummaryText(const SectionResult& r, const std::string& input,
                               const std::string& out) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "%s:\n"
                "  outer diameter          %.3f mm\n"
                "  area (material)         %.4g mm^2\n"
                "  linear density          %.4g kg/m\n"
                "  axial stiffness EA      %.4g N\n"
                "  bending stiffness EI    %.4g N m^2 (max), %.4g N m^2 (min), stiffest about "
                "the axis at %.1f deg from x\n"
                "  bending, wires slipping %.4g N m^2\n"
                "  torsional stiffness GJ  %.4g N m^2 (+/- %.2g), wires slipping %.4g N m^2\n",
                input.c_str(), 1e3 * r.outer_diameter, 1e6 * r.area, r.linear_density,
                r.axial_stiffness, r.bending_max, r.bending_min,
                r.principal_angle * 180.0 / std::numbers::pi, r.bending_unbonded,
                r.torsion.torsional_stiffness, r.torsion.error_estimate, r.torsion_unbonded);
  std::string text = buf;
  for (const std::string& note : r.notes) text += "  note: " + note + "\n";
  text += out.empty() ? "  (all figures as JSON: --out FILE or --format json)\n"
                      : "  (all figures as JSON in " + out + ")\n";
  return text;
}

// --out must name a new or existing file that is none of the run's inputs: SECTION.json and the
// material library it names would otherwise be replaced by the result.
void CheckSectionOut(const std::string& out, const std::vector<std::string>& inputs) {
  std::error_code ec;
  if (std::filesystem::is_directory(out, ec))
    throw InvalidInput("--out " + out + ": is a folder; name a file");
  for (const std::string& in : inputs) {
    if (!in.empty() && std::filesystem::equivalent(in, out, ec) && !ec)
      throw InvalidInput("--out " + out + ": is the input " + in +
                         "; write the result to another file (inputs are never overwritten)");
  }
}

}  // namespace

void RegisterSectionCommand(CLI::App& app, int* exit_code) {
  auto* cmd = app.add_subcommand(
      "section",
      "Bending stiffness matrix, principal axes and stiffnesses, torsional stiffness (numerical "
      "Prandtl, with error estimate) and linear density of a composite cross-section");
  struct Options {
    std::string input;
    std::string out;
    int cells = 0;
    int levels = 0;
    std::string format = "auto";
  };
  auto options = std::make_shared<Options>();
  cmd->add_option("SECTION", options->input, "SECTION.json (format cablefit-section/1)")
      ->required();
  CLI::Option* out_option = cmd->add_option(
      "--out", options->out,
      "also write the result JSON to this file (atomically; never one of the inputs)");
  cmd->add_option("--cells", options->cells,
                  "torsion: grid cells across the section on the finest grid (overrides file)");
  cmd->add_option("--levels", options->levels,
                  "torsion: number of nested grids for the error estimate (overrides file)");
  cmd->add_option("--format", options->format,
                  "standard output: text (a summary with units), json (the result JSON, as "
                  "--out writes it), auto (text on a terminal, json when piped)")
      ->check(CLI::IsMember({"auto", "text", "json"}))
      ->capture_default_str();
  cmd->callback([options, exit_code, out_option] {
    if (out_option->count() > 0 && options->out.empty())
      throw InvalidInput("--out: the output file name is empty");
    if (!options->out.empty()) CheckSectionOut(options->out, {options->input});
    SectionInput input = ReadSectionFile(options->input);
    if (!options->out.empty()) CheckSectionOut(options->out, {input.library});
    if (options->cells > 0) input.torsion.finest_cells = options->cells;
    if (options->levels > 0) input.torsion.levels = options->levels;
    std::string why;
    if (!input.torsion.IsValid(&why)) throw InvalidInput("--cells/--levels: " + why);
    SectionResult result;
    try {
      result = ComputeSection(input.spec, input.torsion);
    } catch (const FileError&) {
      throw;
    } catch (const InvalidInput& e) {
      throw FileError(options->input, e.what());
    }
    json::Json out = SectionResultToJson(result, input, options->input);
    out["provenance"] = ProvenanceJson({{"section", options->input}});
    if (!options->out.empty()) json::WriteJsonFile(options->out, out, 2);
    // Scripts read the JSON (cli-v1: "JSON out"); a person at a terminal gets the figures.
    const bool text = options->format == "text" ||
                      (options->format == "auto" && ::isatty(::fileno(stdout)) == 1);
    if (text)
      std::cout << SectionSummaryText(result, options->input, options->out);
    else
      std::cout << out.dump(2, ' ', false, json::Json::error_handler_t::replace) << std::endl;
    *exit_code = kExitOk;
  });
}

}  // namespace cablefit::addin
