#include "cablefit/cli/commands.h"

int main(int argc, char** argv) { return cablefit::addin::RunCommandLine(argc, argv); }
