// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#include <dealvem/app/input_parsing.h>
#include <dealvem/app/mesh_parameters.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/mesh_io.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <tuple>

namespace dealvem
{
  namespace
  {
    /**
     * The parameters of a generator class G (SpurGear, GearRack) as G's
     * constructor completes them, checked now: G's refusal is rethrown
     * with the parameter section @p section named in place of G's own
     * prefix ("SpurGear: ", "GearRack: ") and without
     * the stack trace.
     */
    template <class G>
    typename G::Parameters
    checked_in_section(const typename G::Parameters &parameters, const std::string &section)
    {
      try
        {
          return G(parameters).parameters();
        }
      catch (const std::exception &e)
        {
          std::string what = e.what();
          for (const std::string prefix : {"SpurGear: ", "GearRack: "})
            if (const auto at = what.find(prefix); at != std::string::npos)
              {
                what = what.substr(at + prefix.size());
                break;
              }
          if (const auto end = what.find("Stacktrace"); end != std::string::npos)
            what = what.substr(0, end);
          AssertThrow(false,
                      dealii::ExcMessage("Parameter section '" + section + "': " + InputParsing::trim(what)));
        }
      return parameters; // not reached
    }

    void
    declare_gear_parameters(dealii::ParameterHandler &prm);
    void
    declare_rack_parameters(dealii::ParameterHandler &prm);
  }


  void
  MeshParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    using dealii::Patterns::Selection;
    prm.declare_entry("Type", "voronoi",
                      Selection("structured quads|structured triangles|perturbed quads|voronoi|"
                                "nonconvex|spur gear|gear rack|vtk file|gridin file"),
                      "Mesh source. Generators work on the rectangle given by the corners; 'spur gear' "
                      "meshes the involute gear of the subsection 'Gear' (boundary ids 0 bore, 1 teeth, "
                      "2 and 3 the sides of a sector), 'gear rack' the rack of the subsection 'Rack' (0 the back "
                      "line, 1 the teeth, 2 the left side, 3 the right side); "
                      "'vtk file' reads a polygon mesh in legacy VTK format; 'gridin file' "
                      "reads any format of deal.II's GridIn (gmsh .msh: physical lines become "
                      "boundary ids, physical surfaces material ids). In a convergence study a "
                      "'gridin file' mesh is refined (Triangulation::refine_global) before it is "
                      "converted; a file name containing '{cycle}' reads one file per level "
                      "instead (cycle 0, 1, ...), which keeps curved boundaries curved.");
    prm.declare_entry("Lower left corner", "0, 0", Anything(),
                      "Lower left corner x, y of the rectangle of the generators.");
    prm.declare_entry("Upper right corner", "1, 1", Anything(),
                      "Upper right corner x, y of the rectangle of the generators.");
    prm.declare_entry("Subdivisions", "8, 8", Anything(),
                      "Number of cells nx, ny of the structured, perturbed and non-convex generators.");
    prm.declare_entry("Number of cells", "64", Integer(1),
                      "Number of Voronoi cells.");
    prm.declare_entry("Lloyd iterations", "20", Integer(0),
                      "Number of Lloyd iterations of the centroidal Voronoi generator.");
    prm.declare_entry("Perturbation", "0.2", Double(0, 0.49),
                      "Random vertex perturbation of 'perturbed quads', relative to the cell size.");
    prm.declare_entry("Non-convex depth", "0.3", Double(0.01, 0.49),
                      "Depth of the reflex vertex of the 'nonconvex' cells, relative to the cell height.");
    prm.declare_entry("Seed", "1", Integer(0),
                      "Seed of the random generators (same seed, same mesh).");
    prm.declare_entry("File name", "", Anything(),
                      "Mesh file for 'vtk file' and 'gridin file' (relative to the parameter file).");
    prm.declare_entry("Material id", "0", Anything(),
                      "Material (body) id given to every cell of a generated mesh; for a mesh file, the "
                      "material id its cells have (one-body problems), as a number or as the name of a "
                      "gmsh physical surface.");
    prm.declare_entry("Boundary id offset", "0", Integer(0, 200),
                      "Added to every boundary id of the mesh (generators use 0 left, 1 right, "
                      "2 bottom, 3 top), so that the bodies of a contact problem have distinct ids.");
    prm.declare_entry("Parts as bodies", "false", dealii::Patterns::Bool(),
                      "Contact problems, file meshes: every material id of the file (a gmsh physical "
                      "surface, the VTK field material_id) is a body of its own, numbered in the order "
                      "of the ids from this section's body index on; the parts may be meshed "
                      "independently (non-matching at their interfaces) or share nodes ('gridin file': "
                      "shared nodes are duplicated, the faces between parts become boundary edges with "
                      "id 0). Materials per part: 'Material/Part materials'. Usually combined with "
                      "'Contact/Pairs = auto'.");
    prm.declare_entry("Shift", "0, 0", Anything(), "Translation x, y applied to the mesh.");
    prm.declare_entry("Transformation", "", Anything(),
                      "Map of the vertices 'x_new, y_new' as muparser expressions in x, y (with "
                      "pi), applied before the shift; edges stay straight and the mapped mesh is "
                      "validated. Example for a sloped top: 'x, y*(1 + 0.2*x)'. Empty: none.");
    declare_gear_parameters(prm);
    declare_rack_parameters(prm);
  }



  namespace
  {
    const double degree = M_PI / 180;

    /// The entries of subsection 'Gear' (Type = spur gear).
    void
    declare_gear_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Anything;
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;
      prm.enter_subsection("Gear");
      prm.declare_entry("Module", "1", Double(0), "Module m of the involute spur gear (Type = spur gear).");
      prm.declare_entry("Number of teeth", "20", Integer(5, 10000), "Number of teeth z.");
      prm.declare_entry("Pressure angle", "20", Double(0, 35), "Pressure angle of the basic rack, in degrees.");
      prm.declare_entry("Profile shift", "0", Double(-2, 2), "Profile shift coefficient x.");
      prm.declare_entry("Addendum", "1", Double(0), "Addendum coefficient h_a* (tip radius r + m (h_a* + x)).");
      prm.declare_entry("Dedendum", "1.25", Double(0),
                        "Dedendum coefficient h_f* (root radius r - m (h_f* - x)), the rack's addendum.");
      prm.declare_entry("Rack tip radius", "0.38", Double(0),
                        "Tip radius coefficient of the rack rho_f* (the root fillet is the trochoid its "
                        "rounded corner cuts).");
      prm.declare_entry("Backlash", "0", Double(0),
                        "Backlash allowance of this gear: the teeth thinned by this length along the "
                        "reference circle.");
      prm.declare_entry("Tip relief", "0", Double(0),
                        "Tip relief amount C_a at the tip (a length along the flank normal); 0: none.");
      prm.declare_entry("Tip relief radius", "0", Double(0),
                        "Radius where the tip relief starts; 0: halfway between the reference and the tip "
                        "radius.");
      prm.declare_entry("Tip relief shape", "linear", dealii::Patterns::Selection("linear|parabolic"),
                        "How the tip relief grows with the roll length: linear or parabolic.");
      prm.declare_entry("Bore radius", "0", Double(0),
                        "Radius of the bore of an external gear; 0: half the root radius.");
      prm.declare_entry("Internal", "false", dealii::Patterns::Bool(),
                        "An internal (ring) gear: the teeth point toward the centre, the body reaches out to "
                        "'Rim radius' (boundary id 0 is the rim circle); its root fillet is a circle of radius "
                        "'Rack tip radius' times m tangent to flank and root circle. No profile shift or tip relief "
                        "yet.");
      prm.declare_entry("Rim radius", "0", Double(0),
                        "Outer radius of an internal gear's rim; 0: the root radius plus 3 modules.");
      prm.declare_entry("Centre", "0, 0", Anything(), "Centre x, y of the gear.");
      prm.declare_entry("Rotation", "0", Double(), "Polar angle of the axis of tooth 0, in degrees.");
      prm.declare_entry("Teeth", "all", Anything(),
                        "The teeth meshed: 'all' (the whole gear) or 'first, count' (a sector from the "
                        "middle of the space before tooth 'first' to the middle of the space after the "
                        "last; teeth are numbered counter-clockwise from tooth 0).");
      prm.declare_entry("Global refinements", "1", Integer(0, 8),
                        "Global refinements of the block mesh (about 6 cells across a tooth at 0).");
      prm.declare_entry("Flank cell size", "0", Double(0),
                        "Cell size the flanks are refined to (0: no local refinement).");
      prm.declare_entry("Refined teeth", "all", Anything(),
                        "The teeth whose flanks are refined: 'all' (the meshed ones) or 'first, count' "
                        "(numbered as 'Teeth', modulo the number of teeth; each must be meshed).");
      prm.declare_entry("Refined radii", "auto", Anything(),
                        "Radii 'from, to' of the refined flank zone; 'auto': the flank from the form radius "
                        "to the tip.");
      prm.declare_entry("Refinement layers", "2", Double(0.1, 100),
                        "Cells within this many cell sizes of the flank zone are refined.");
      prm.leave_subsection();
    }

    /// The entries of subsection 'Rack' (Type = gear rack).
    void
    declare_rack_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Anything;
      using dealii::Patterns::Double;
      using dealii::Patterns::Integer;
      prm.enter_subsection("Rack");
      prm.declare_entry("Module", "1", Double(0), "Module m of the rack (Type = gear rack).");
      prm.declare_entry("Number of teeth", "5", Integer(1, 10000), "Number of teeth.");
      prm.declare_entry("Pressure angle", "20", Double(0, 45),
                        "Angle of the straight flanks from the normal of the pitch line, in degrees.");
      prm.declare_entry("Profile shift", "0", Double(-2, 2),
                        "Profile offset coefficient x: the datum line of the profile x m above the pitch line.");
      prm.declare_entry("Addendum", "1", Double(0), "Addendum coefficient h_a* (tip line (h_a* + x) m above the "
                                                    "pitch line).");
      prm.declare_entry("Dedendum", "1.25", Double(0),
                        "Dedendum coefficient h_f* (root line (h_f* - x) m below the pitch line).");
      prm.declare_entry("Root fillet radius", "0.38", Double(0),
                        "Root fillet radius coefficient rho_f* (a circle of radius rho_f* m tangent to flank "
                        "and root line); 0: sharp root corners.");
      prm.declare_entry("Backlash", "0", Double(),
                        "Backlash allowance: each tooth thinned by this length along the pitch line.");
      prm.declare_entry("Body depth", "0", Double(0),
                        "Depth of the body below the root line (the back line, boundary id 0, lies this "
                        "far below it); 0: 3 modules.");
      prm.declare_entry("Pitch line height", "0", Double(), "Height y of the pitch line (the teeth point to +y).");
      prm.declare_entry("Position", "0", Double(), "Position x of the axis of tooth 0.");
      prm.declare_entry("Global refinements", "1", Integer(0, 8),
                        "Global refinements of the block mesh (about 6 cells across a tooth at 0).");
      prm.declare_entry("Flank cell size", "0", Double(0),
                        "Cell size the refined flanks are refined to (0: no local refinement).");
      prm.declare_entry("Fillet cell size", "0", Double(0),
                        "Cell size the root fillets below the refined flanks are refined to (0: none).");
      prm.declare_entry("Refined teeth", "all", Anything(),
                        "The teeth whose flanks are refined: 'all' or 'first, count' (teeth numbered from "
                        "0, left to right).");
      prm.declare_entry("Refined flank", "both", dealii::Patterns::Selection("both|left|right"),
                        "The flank of each refined tooth: both, left (facing -x) or right (facing +x).");
      prm.declare_entry("Refined heights", "auto", Anything(),
                        "Heights 'from, to' above the pitch line of the refined flank zone; 'auto': the "
                        "flank from the fillet to the tip.");
      prm.declare_entry("Refinement layers", "2", Double(0.1, 100),
                        "Cells within this many cell sizes of the flank zone are refined.");
      prm.leave_subsection();
    }

    /// 'all' -> {0, 0}, 'first, count' -> {first, count}.
    std::pair<unsigned int, unsigned int>
    parse_teeth(const std::string &text, const std::string &name)
    {
      if (InputParsing::trim(text) == "all")
        return {0, 0};
      const auto parts = InputParsing::split(text, ',');
      AssertThrow(parts.size() == 2,
                  dealii::ExcMessage("Parameter '" + name + "': expected 'all' or 'first, count', got '" + text + "'."));
      const unsigned int first = InputParsing::parse_unsigned(parts[0], name);
      const unsigned int count = InputParsing::parse_unsigned(parts[1], name);
      AssertThrow(count >= 1, dealii::ExcMessage("Parameter '" + name + "': the count must be at least 1."));
      return {first, count};
    }

    dealii::Point<2>
    parse_point(const std::string &s, const std::string &name)
    {
      const auto parts = InputParsing::split(s, ',');
      AssertThrow(parts.size() == 2,
                  dealii::ExcMessage("Parameter '" + name + "': expected 'x, y', got '" + s + "'."));
      return dealii::Point<2>(InputParsing::parse_double(parts[0], name),
                              InputParsing::parse_double(parts[1], name));
    }
  } // namespace



  void
  MeshParameters::parse_parameters(dealii::ParameterHandler &prm, const std::string &section)
  {
    type        = prm.get("Type");
    lower_left  = parse_point(prm.get("Lower left corner"), section + "/Lower left corner");
    upper_right = parse_point(prm.get("Upper right corner"), section + "/Upper right corner");
    AssertThrow(upper_right[0] > lower_left[0] && upper_right[1] > lower_left[1],
                dealii::ExcMessage("Parameters '" + section +
                                   "/Lower left corner' and 'Upper right corner': the upper right "
                                   "corner must lie above and right of the lower left corner."));
    const auto sub = InputParsing::split(prm.get("Subdivisions"), ',');
    AssertThrow(sub.size() == 2,
                dealii::ExcMessage("Parameter '" + section + "/Subdivisions': expected 'nx, ny'."));
    nx = InputParsing::parse_unsigned(sub[0], section + "/Subdivisions");
    ny = InputParsing::parse_unsigned(sub[1], section + "/Subdivisions");
    AssertThrow(nx >= 1 && ny >= 1,
                dealii::ExcMessage("Parameter '" + section + "/Subdivisions' must be at least 1, 1."));
    n_cells          = prm.get_integer("Number of cells");
    lloyd_iterations = prm.get_integer("Lloyd iterations");
    perturbation     = prm.get_double("Perturbation");
    nonconvex_depth  = prm.get_double("Non-convex depth");
    seed             = prm.get_integer("Seed");
    file_name        = prm.get("File name");
    material_name    = InputParsing::trim(prm.get("Material id"));
    material_id      = 0;
    if (!material_name.empty() && material_name.find_first_not_of("0123456789") == std::string::npos)
      {
        material_id = InputParsing::parse_unsigned(material_name, section + "/Material id");
        AssertThrow(material_id <= 254, dealii::ExcMessage("Parameter '" + section + "/Material id' is " +
                                                           material_name + ": material ids of the parameter file "
                                                           "are 0..254."));
        material_name.clear();
      }
    else
      AssertThrow(!material_name.empty() && type == "gridin file",
                  dealii::ExcMessage("Parameter '" + section + "/Material id' is '" + material_name +
                                     "': a number 0..254 is expected" +
                                     (type == "gridin file" ? std::string(".") :
                                                              std::string(" (a name of a physical surface is read "
                                                                          "from a gmsh file only, Type = gridin "
                                                                          "file)."))));
    this->section = section;
    boundary_id_offset = prm.get_integer("Boundary id offset");
    parts_as_bodies    = prm.get_bool("Parts as bodies");
    AssertThrow(!parts_as_bodies || type.find("file") != std::string::npos,
                dealii::ExcMessage("Parameter '" + section + "/Parts as bodies' is true, but 'Type' is '" + type +
                                   "': parts come from the material ids of a mesh file ('vtk file' or "
                                   "'gridin file')."));
    shift            = parse_point(prm.get("Shift"), section + "/Shift");
    transformation   = prm.get("Transformation");
    if (!InputParsing::trim(transformation).empty())
      {
        const auto e = InputParsing::split(transformation, ',');
        AssertThrow(e.size() == 2, dealii::ExcMessage("Parameter '" + section +
                                                      "/Transformation': expected 'x_new, y_new'."));
        InputParsing::ParsedFunction f(e, {{"pi", M_PI}}, section + "/Transformation");
      }
    AssertThrow(type.find("file") == std::string::npos || !file_name.empty(),
                dealii::ExcMessage("Parameter '" + section + "/File name' is empty but 'Type' is '" +
                                   type + "'."));
    parse_gear_parameters(prm);
    parse_rack_parameters(prm);
  }



  void
  MeshParameters::parse_gear_parameters(dealii::ParameterHandler &prm)
  {
    const std::string name = section + "/Gear";
    prm.enter_subsection("Gear");
    gear                   = SpurGear::Parameters();
    gear.module            = prm.get_double("Module");
    gear.n_teeth           = prm.get_integer("Number of teeth");
    gear.pressure_angle    = prm.get_double("Pressure angle") * degree;
    gear.profile_shift     = prm.get_double("Profile shift");
    gear.addendum          = prm.get_double("Addendum");
    gear.dedendum          = prm.get_double("Dedendum");
    gear.rack_tip_radius   = prm.get_double("Rack tip radius");
    gear.backlash          = prm.get_double("Backlash");
    gear.tip_relief        = prm.get_double("Tip relief");
    gear.tip_relief_radius = prm.get_double("Tip relief radius");
    gear.relief_shape      = prm.get("Tip relief shape") == "parabolic" ? SpurGear::ReliefShape::parabolic :
                                                                          SpurGear::ReliefShape::linear;
    gear.bore_radius       = prm.get_double("Bore radius");
    gear.internal          = prm.get_bool("Internal");
    gear.rim_radius        = prm.get_double("Rim radius");
    gear.center            = parse_point(prm.get("Centre"), name + "/Centre");
    gear.rotation          = prm.get_double("Rotation") * degree;
    gear_mesh              = PolygonalMeshGenerators::GearMeshSettings();
    std::tie(gear_mesh.first_tooth, gear_mesh.n_teeth) = parse_teeth(prm.get("Teeth"), name + "/Teeth");
    gear_mesh.n_global_refinements = prm.get_integer("Global refinements");
    gear_mesh.flank_cell_size      = prm.get_double("Flank cell size");
    std::tie(gear_mesh.first_refined_tooth, gear_mesh.n_refined_teeth) =
      parse_teeth(prm.get("Refined teeth"), name + "/Refined teeth");
    const std::string radii = InputParsing::trim(prm.get("Refined radii"));
    if (radii != "auto")
      {
        const dealii::Point<2> r = parse_point(radii, name + "/Refined radii");
        AssertThrow(r[0] > 0 && r[1] > r[0],
                    dealii::ExcMessage("Parameter '" + name + "/Refined radii': expected 'auto' or 'from, to' with "
                                       "0 < from < to, got '" + radii + "'."));
        gear_mesh.refine_from_radius = r[0];
        gear_mesh.refine_to_radius   = r[1];
      }
    gear_mesh.layers = prm.get_double("Refinement layers");
    prm.leave_subsection();
    if (type == "spur gear")
      {
        // check the data now, naming the section
        gear = checked_in_section<SpurGear>(gear, name);
        // a refined tooth outside the meshed sector would leave the mesh
        // unrefined without a word
        const unsigned int z = gear.n_teeth;
        if (gear_mesh.flank_cell_size > 0 && gear_mesh.n_teeth > 0 && gear_mesh.n_teeth < z &&
            gear_mesh.n_refined_teeth > 0)
          for (unsigned int i = 0; i < gear_mesh.n_refined_teeth; ++i)
            {
              const unsigned int k = (gear_mesh.first_refined_tooth + i) % z;
              AssertThrow((k + z - gear_mesh.first_tooth % z) % z < gear_mesh.n_teeth,
                          dealii::ExcMessage("Parameter '" + name + "/Refined teeth': tooth " + std::to_string(k) +
                                             " is not meshed ('Teeth' is the sector of teeth " +
                                             std::to_string(gear_mesh.first_tooth % z) + " to " +
                                             std::to_string((gear_mesh.first_tooth + gear_mesh.n_teeth - 1) % z) +
                                             ", counted counter-clockwise modulo " + std::to_string(z) + ")."));
            }
      }
  }



  void
  MeshParameters::parse_rack_parameters(dealii::ParameterHandler &prm)
  {
    const std::string name = section + "/Rack";
    prm.enter_subsection("Rack");
    rack                    = GearRack::Parameters();
    rack.module             = prm.get_double("Module");
    rack.n_teeth            = prm.get_integer("Number of teeth");
    rack.pressure_angle     = prm.get_double("Pressure angle") * degree;
    rack.profile_shift      = prm.get_double("Profile shift");
    rack.addendum           = prm.get_double("Addendum");
    rack.dedendum           = prm.get_double("Dedendum");
    rack.root_fillet_radius = prm.get_double("Root fillet radius");
    rack.backlash           = prm.get_double("Backlash");
    rack.body_depth         = prm.get_double("Body depth");
    rack.pitch_line_height  = prm.get_double("Pitch line height");
    rack.position           = prm.get_double("Position");
    rack_mesh               = PolygonalMeshGenerators::RackMeshSettings();
    rack_mesh.n_global_refinements = prm.get_integer("Global refinements");
    rack_mesh.flank_cell_size      = prm.get_double("Flank cell size");
    rack_mesh.fillet_cell_size     = prm.get_double("Fillet cell size");
    rack_mesh.layers               = prm.get_double("Refinement layers");
    const auto [first, count]      = parse_teeth(prm.get("Refined teeth"), name + "/Refined teeth");
    using Flank                    = PolygonalMeshGenerators::RackMeshSettings::Flank;
    const std::string flank        = prm.get("Refined flank");
    PolygonalMeshGenerators::RackMeshSettings::FlankZone zone;
    zone.flank                = flank == "left" ? Flank::left : flank == "right" ? Flank::right : Flank::both;
    const std::string heights = InputParsing::trim(prm.get("Refined heights"));
    if (heights != "auto")
      {
        const dealii::Point<2> h = parse_point(heights, name + "/Refined heights");
        AssertThrow(h[1] > h[0], dealii::ExcMessage("Parameter '" + name + "/Refined heights': expected 'auto' or "
                                                    "'from, to' with from < to, got '" + heights + "'."));
        zone.from_height = h[0];
        zone.to_height   = h[1];
      }
    prm.leave_subsection();
    const unsigned int n_refined = count == 0 ? rack.n_teeth : count;
    for (unsigned int k = first; k < first + n_refined; ++k)
      {
        AssertThrow(type != "gear rack" || k < rack.n_teeth,
                    dealii::ExcMessage("Parameter '" + name + "/Refined teeth': tooth " + std::to_string(k) +
                                       " is not one of the rack's " + std::to_string(rack.n_teeth) +
                                       " teeth (0 to " + std::to_string(rack.n_teeth - 1) + ")."));
        zone.tooth = k;
        rack_mesh.zones.push_back(zone);
      }
    if (type == "gear rack")
      {
        // check the data now, naming the section
        rack = checked_in_section<GearRack>(rack, name);
      }
  }



  void
  MeshParameters::create_mesh(PolygonalMesh<2>  &mesh,
                              const unsigned int refinement,
                              const std::string &base_directory) const
  {
    const unsigned int f = 1u << refinement;
    namespace G          = PolygonalMeshGenerators;
    if (type == "structured quads")
      G::structured_quads(mesh, lower_left, upper_right, nx * f, ny * f);
    else if (type == "structured triangles")
      G::structured_triangles(mesh, lower_left, upper_right, nx * f, ny * f);
    else if (type == "perturbed quads")
      G::perturbed_quads(mesh, lower_left, upper_right, nx * f, ny * f, perturbation, seed);
    else if (type == "voronoi")
      G::voronoi(mesh, lower_left, upper_right, n_cells * f * f, lloyd_iterations, seed);
    else if (type == "nonconvex")
      G::nonconvex(mesh, lower_left, upper_right, nx * f, ny * f, nonconvex_depth);
    else if (type == "spur gear")
      {
        auto settings = gear_mesh;
        settings.n_global_refinements += refinement;
        G::spur_gear(mesh, SpurGear(gear), settings);
      }
    else if (type == "gear rack")
      {
        auto settings = rack_mesh;
        settings.n_global_refinements += refinement;
        G::gear_rack(mesh, GearRack(rack), settings);
      }
    else
      {
        // one file per level ("{cycle}" in the name), or the file refined
        const std::string placeholder = "{cycle}";
        std::string       path        = file_name;
        const auto        at          = path.find(placeholder);
        const bool        per_level   = (at != std::string::npos);
        if (per_level)
          path.replace(at, placeholder.size(), std::to_string(refinement));
        AssertThrow(refinement == 0 || per_level || type == "gridin file",
                    dealii::ExcMessage("A polygon mesh read from the VTK file '" + file_name +
                                       "' cannot be refined in a convergence study; name one file per "
                                       "level with '{cycle}' in the file name."));
        if (!path.empty() && path[0] != '/' && !base_directory.empty())
          path = base_directory + "/" + path;
        if (type == "vtk file")
          MeshIO::read_vtk(mesh, path);
        else
          G::from_gridin_file(mesh, path, per_level ? 0 : refinement, parts_as_bodies);
      }
    if (type.find("file") == std::string::npos)
      for (unsigned int c = 0; c < mesh.n_cells(); ++c)
        mesh.set_material_id(c, material_id);
    shift_boundary_ids(mesh, boundary_id_offset);
    if (!InputParsing::trim(transformation).empty())
      {
        const InputParsing::ParsedFunction f(InputParsing::split(transformation, ','),
                                             {{"pi", M_PI}}, "Transformation");
        PolygonalMesh<2> mapped;
        mapped.name = mesh.name + " (transformed)";
        for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
          mapped.add_vertex(dealii::Point<2>(f.value(mesh.vertex(v), 0), f.value(mesh.vertex(v), 1)));
        for (unsigned int c = 0; c < mesh.n_cells(); ++c)
          mapped.add_cell(mesh.cell(c).vertices, mesh.cell(c).material_id);
        for (unsigned int e = 0; e < mesh.n_edges(); ++e)
          if (mesh.edge(e).at_boundary())
            mapped.set_boundary_id(mesh.edge(e).vertices[0], mesh.edge(e).vertices[1],
                                   mesh.edge(e).boundary_id);
        mapped.finalize();
        mesh = mapped;
      }
    if (shift.norm() > 0)
      mesh.shift(shift);
  }



  void
  MeshParameters::load_physical_names(const std::string &base_directory)
  {
    physical_names = MeshIO::PhysicalNames();
    std::string path = file_name;
    const auto  at   = path.find("{cycle}");
    if (at != std::string::npos)
      path.replace(at, 7, "0");
    if (!path.empty() && path[0] != '/' && !base_directory.empty())
      path = base_directory + "/" + path;
    const std::string ext = std::filesystem::path(path).extension().string();
    if (type == "gridin file" && (ext == ".msh" || ext.empty()) && std::filesystem::is_regular_file(path))
      physical_names = MeshIO::read_msh_physical_names(path);
    // the boundary ids as the mesh will have them
    for (auto &[n, id] : physical_names.boundary_ids)
      {
        AssertThrow(id + boundary_id_offset <= InputParsing::max_boundary_id,
                    dealii::ExcMessage("Parameter '" + section + "/Boundary id offset': the physical curve '" + n +
                                       "' of '" + file_name + "' would get the id " +
                                       std::to_string(id + boundary_id_offset) + ", out of range (0..254)."));
        id = dealii::types::boundary_id(id + boundary_id_offset);
      }
    if (!material_name.empty())
      material_id = InputParsing::parse_id_or_name(material_name, section + "/Material id",
                                                   physical_names.material_ids, "material id",
                                                   physical_names.list() + " (file '" + file_name + "')");
  }



  std::string
  MeshParameters::description() const
  {
    std::ostringstream s;
    s << type;
    if (type == "voronoi")
      s << ", " << n_cells << " cells, " << lloyd_iterations << " Lloyd iterations, seed " << seed;
    else if (type.find("file") != std::string::npos)
      s << " '" << file_name << "'";
    else if (type == "spur gear")
      s << ", z " << gear.n_teeth << ", m " << gear.module
        << (gear_mesh.n_teeth == 0 ? std::string(", whole") :
                                     ", teeth " + std::to_string(gear_mesh.first_tooth) + " to " +
                                       std::to_string(gear_mesh.first_tooth + gear_mesh.n_teeth - 1));
    else if (type == "gear rack")
      s << ", " << rack.n_teeth << " teeth, m " << rack.module;
    else
      s << ", " << nx << " x " << ny;
    return s.str();
  }


  void
  MeshParameters::shift_boundary_ids(PolygonalMesh<2> &mesh, const unsigned int offset, const std::string &what)
  {
    if (offset == 0)
      return;
    for (unsigned int e = 0; e < mesh.n_edges(); ++e)
      if (mesh.edge(e).at_boundary())
        {
          const unsigned int id = mesh.edge(e).boundary_id + offset;
          AssertThrow(id <= InputParsing::max_boundary_id,
                      dealii::ExcMessage(what + ": id " + std::to_string(id) + " is out of range (0..254)."));
          mesh.set_edge_boundary_id(e, dealii::types::boundary_id(id));
        }
  }
} // namespace dealvem
