// Writes every face of an IGES file as a root entity of its own, in no group, as exporters that
// write no groups do: flatten_iges IN.igs OUT.igs. Built by hand against OpenCASCADE:
//   g++ -std=c++20 -I/usr/include/opencascade flatten_iges.cc -o flatten_iges -lTKernel -lTKMath \
//       -lTKG2d -lTKG3d -lTKGeomBase -lTKBRep -lTKTopAlgo -lTKXSBase -lTKIGES -lTKShHealing
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <TopExp_Explorer.hxx>

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  IGESControl_Reader reader;
  if (reader.ReadFile(argv[1]) != IFSelect_RetDone) return 1;
  reader.TransferRoots();
  IGESControl_Writer writer("MM", 0);
  for (TopExp_Explorer ex(reader.OneShape(), TopAbs_FACE); ex.More(); ex.Next())
    writer.AddShape(ex.Current());
  writer.ComputeModel();
  return writer.Write(argv[2]) ? 0 : 1;
}
