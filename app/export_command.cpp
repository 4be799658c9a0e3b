// `tendril export MODEL --ccx FILE --vtk FILE --obj FILE --ply FILE --glb
// FILE`: a model database (m:save) as a CalculiX input deck (io/ccx.hpp,
// docs/calculix.md), a VTK file of the state and its results for ParaView
// (io/vtk.hpp), an OBJ (io/obj.hpp), a PLY (io/ply.hpp) or glTF
// (io/gltf.hpp); at least one.
// The results come from the saved state: forces, moments and reactions
// after one force evaluation, no step (stresses need a section: m:export_vtk).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "io/ccx.hpp"
#include "io/gltf.hpp"
#include "io/model_xml.hpp"
#include "io/obj.hpp"
#include "io/ply.hpp"
#include "io/vtk.hpp"
#include "physics/solver.hpp"

namespace tendril::app {

namespace {

struct Outputs {
  std::string model, ccx, vtk, obj, ply, glb, colour = "kind";
};

int export_model(const Outputs& o) {
  if (o.ccx.empty() && o.vtk.empty() && o.obj.empty() && o.ply.empty() && o.glb.empty())
    throw UsageError("nothing to write: give --ccx, --vtk, --obj, --ply or --glb FILE");
  Model model;
  SolverSettings settings;
  load_model_xml(o.model, model, settings);
  Solver solver(model);
  solver.settings = settings;
  solver.compute_forces();  // the reactions of the saved state
  auto done = [&](const std::string& path) {
    std::printf("%s: %zu particles, %zu blocks -> %s\n", o.model.c_str(), model.particle_count(), model.block_count(),
                path.c_str());
  };
  if (!o.ccx.empty()) save_ccx(model, o.ccx), done(o.ccx);
  if (!o.vtk.empty()) save_vtk(model, o.vtk), done(o.vtk);
  if (!o.obj.empty()) save_obj(model, o.obj), done(o.obj);
  if (!o.ply.empty()) save_ply(model, o.ply), done(o.ply);
  if (!o.glb.empty()) save_gltf(model, o.glb, GltfOptions{o.colour}), done(o.glb);
  return kOk;
}

}  // namespace

Command export_command() {
  return {"export",
          "writes a model database (m:save) as a CalculiX deck (docs/calculix.md), VTK with results for ParaView, "
          "OBJ, PLY or glTF",
          [](CLI::App& cli) {
            auto o = std::make_shared<Outputs>();
            cli.add_option("--ccx", o->ccx, "the CalculiX deck to write (ccx -i NAME reads NAME.inp)")->type_name("FILE");
            cli.add_option("--vtk", o->vtk, "a VTK file (.vtu: VTK XML, .vtp: VTK XML poly data, else legacy) with per-element results and reactions")
                ->type_name("FILE");
            cli.add_option("--obj", o->obj, "a Wavefront OBJ, one group per block")->type_name("FILE");
            cli.add_option("--ply", o->ply, "a PLY of the particles, line elements and patch faces")->type_name("FILE");
            cli.add_option("--glb", o->glb, "a glTF 2.0 binary for three.js, Blender, Rhino 8 (y up)")->type_name("FILE");
            cli.add_option("--colour", o->colour, "what colours the --glb: kind, axial, moment or s1")
                ->check(CLI::IsMember({"kind", "axial", "moment", "s1"}))
                ->type_name("FIELD");
            cli.add_option("model", o->model, "a model database written by m:save")
                ->required()
                ->check(CLI::ExistingPath)
                ->type_name("MODEL");
            return [o] { return export_model(*o); };
          }};
}

}  // namespace tendril::app
