// `cablefit section SECTION.json [--out FILE]`: composite cross-section stiffness (cli-v1).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "cablefit/cli/commands.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/app/section_json.h"

namespace cablefit::addin {

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
  };
  auto options = std::make_shared<Options>();
  cmd->add_option("SECTION", options->input, "SECTION.json (format cablefit-section/1)")
      ->required();
  cmd->add_option("--out", options->out, "also write the result JSON to this file (atomically)");
  cmd->add_option("--cells", options->cells,
                  "torsion: grid cells across the section on the finest grid (overrides file)");
  cmd->add_option("--levels", options->levels,
                  "torsion: number of nested grids for the error estimate (overrides file)");
  cmd->callback([options, exit_code] {
    SectionInput input = ReadSectionFile(options->input);
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
    const json::Json out = SectionResultToJson(result, input, options->input);
    if (!options->out.empty()) json::WriteJsonFile(options->out, out, 2);
    std::cout << out.dump(2) << std::endl;
    *exit_code = kExitOk;
  });
}

}  // namespace cablefit::addin
