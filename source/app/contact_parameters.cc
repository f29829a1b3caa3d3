// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
//
// ContactProblem: the parameter file (declaration, body sections, parsing).
#include "contact_problem_internal.h"

#include <dealvem/solvers/p_multigrid.h>
#include <dealvem/vem/vem_element_data.h>

namespace dealvem
{
  using namespace internal::ContactProblemImplementation;



  namespace
  {
    // The material entries of body 0 that only contact problems read, and
    // the sections 'Body 1' to 'Body n_body_sections - 1'.
    void
    declare_body_sections(dealii::ParameterHandler &prm, const unsigned int n_body_sections)
    {
      using namespace dealii::Patterns;
      const std::string part_materials_doc =
        "With 'Mesh/Parts as bodies': the materials of the parts, 'material id : E : nu; ...' (the "
        "ids of the mesh file), or 'material id : E : nu : name' with a material name for 'Contact/Friction "
        "between materials'; parts not listed take this section's Young's modulus, Poisson's ratio and name.";
      const std::string material_name_doc =
        "A name of this body's material (letters, digits, '_', '-', '.'), for 'Contact/Friction between "
        "materials'. Empty: none.";
      prm.enter_subsection("Material");
      prm.declare_entry("Part materials", "", Anything(), part_materials_doc);
      prm.declare_entry("Name", "", Anything(), material_name_doc);
      prm.leave_subsection();
      for (unsigned int b = 1; b < std::max(n_body_sections, 2u); ++b)
        {
          prm.enter_subsection("Body " + std::to_string(b));
          prm.enter_subsection("Mesh");
          MeshParameters::declare_parameters(prm);
          prm.leave_subsection();
          prm.enter_subsection("Material");
          prm.declare_entry("Young's modulus", "", Anything(),
                            "Young's modulus E (> 0) of this body. Empty: the top-level 'Material/Young's "
                            "modulus' (the material of body 0).");
          prm.declare_entry("Poisson's ratio", "", Anything(),
                            "Poisson's ratio nu, -1 < nu < 0.5, of this body. Empty: the top-level "
                            "'Material/Poisson's ratio' (the material of body 0).");
          prm.declare_entry("Part materials", "", Anything(), part_materials_doc);
          prm.declare_entry("Name", "", Anything(), material_name_doc);
          prm.leave_subsection();
          prm.enter_subsection("Exact solution");
          prm.declare_entry("Displacement", "", Anything(),
                            "Exact displacement 'ux, uy' of this body (muparser in x, y, t with the "
                            "function constants), compared with the solution of the last load step at "
                            "t = 'Load steps/Final time' (1 by default). Empty: the top-level 'Exact "
                            "solution' applies to this body too.");
          prm.leave_subsection();
          prm.leave_subsection();
        }
    }

    // The section 'Contact'.
    void
    declare_contact_section(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection("Contact");
      prm.declare_entry("Pairs", "", Anything(),
                        "Contact interfaces 'master id : slave id; ...': boundary parts of two "
                        "different bodies. The master side gives the normal. With Coulomb friction an "
                        "entry may give its own friction coefficient: 'master id : slave id : mu'. The "
                        "entry 'auto' adds the interfaces found by contact detection: boundary edges of "
                        "different bodies that face each other (normals opposite within 'Detection "
                        "angle', apart by at most 'Detection distance' times the edge length), except "
                        "those whose ids carry boundary conditions or explicit pairs; the coarser side "
                        "is the master. The list is printed; <base name>-resultants.csv gives each interface's bodies, "
                        "ids, length and contact force. With finite sliding ('Finite strain/Enabled = true') "
                        "the detection runs in the current configuration at every pairing pass, so contacts "
                        "that open and close anywhere on the free boundary are found, and the results sum "
                        "the detected interfaces of each pair of bodies.");
      prm.declare_entry("Detection distance", "0.5", Double(0, 10),
                        "Pairs = auto: largest distance (gap or overlap) between facing boundary edges, "
                        "relative to the longer of the two edges.");
      prm.declare_entry("Detection angle", "45", Double(1, 89),
                        "Pairs = auto: largest deviation (degrees) of the outward normals of facing "
                        "edges from opposite.");
      prm.declare_entry("Friction between bodies", "", Anything(),
                        "Coulomb friction coefficients by pairs of bodies, 'body a : body b : mu; ...' "
                        "(body indices, '*' for any body; a pair of bodies beats a '*' entry, a later "
                        "entry an earlier one). They apply to detected interfaces and to pairs that give "
                        "no coefficient of their own; others take 'Friction coefficient'.");
      prm.declare_entry("Friction between materials", "", Anything(),
                        "Coulomb friction coefficients by pairs of materials, 'name a : name b : mu; ...' "
                        "(the names of 'Material/Name' or of 'Part materials', '*' for any material). "
                        "They apply where 'Friction between bodies' gives nothing; a pair of names beats a "
                        "'*' entry, a later entry an earlier one.");
      prm.declare_entry("Normal", "unilateral", Selection("tied|unilateral"),
                        "tied: g = 0 at every pair (bilateral); unilateral: g >= 0, pressure >= 0, "
                        "complementarity, by a primal-dual active set.");
      prm.declare_entry("Tangential", "penalty",
                        Selection("frictionless|penalty|multipliers|coulomb|coulomb penalty"),
                        "frictionless; stick by a penalty (see 'Penalty'); stick by Lagrange "
                        "multipliers (exactly tied); Coulomb friction with exact stick by multipliers "
                        "(coulomb) or regularised by the penalty (coulomb penalty): each pair is open, "
                        "sticking or slipping, |tangential traction| <= mu * pressure, solved by a "
                        "semismooth Newton (active set) method per load step.");
      prm.declare_entry("Friction coefficient", "0", Double(),
                        "Coulomb friction coefficient mu >= 0 of the contact pairs that do not give "
                        "their own in 'Pairs' (only with 'Tangential = coulomb' or 'coulomb penalty').");
      prm.declare_entry("Penalty", "0", Double(0),
                        "Tangential stick penalty (stiffness per length and slip, units of E/h). "
                        "0 selects the default rule 'Penalty factor' * E_min / h_min, with E_min the "
                        "smallest Young's modulus and h_min the shortest interface sub-edge.");
      prm.declare_entry("Penalty factor", "1000", Double(0), "Factor of the default penalty rule.");
      prm.declare_entry("Merge fraction", "0.05", Double(1e-6, 0.49),
                        "Node insertion: a node whose closest point on the other side lies closer "
                        "than this times the local edge length to a node of that side is paired with "
                        "it (the two are merged) instead of splitting the edge: no sub-edge shorter "
                        "than this fraction is created.");
      prm.declare_entry("Search distance", "0.25", Double(0),
                        "Node insertion: largest distance between a node and its partner, relative to "
                        "the size of the interface (the diagonal of the bounding box of both contact "
                        "parts). Nodes inside the overlap but farther apart are reported.");
      prm.declare_entry("Coordinate precision", "auto", Anything(),
                        "Node insertion: precision of the mesh coordinates; a gap within it is round-off "
                        "of the mesh files and is closed. 'auto': each contact part's own, the decimal "
                        "grid its coordinates were written on (a file with six significant digits: a "
                        "unit of the sixth digit; none for coordinates computed in double precision, for "
                        "all short binary fractions such as 0.125, and for a grid coarser than 1/100 of "
                        "the part's shortest edge, a lattice the vertices were placed on), a gap within half the two parts' "
                        "grids being closed. A number in [0, 0.01) replaces the detection, for data "
                        "rounded more coarsely than written (coordinates exported in double from a "
                        "six-digit CAD model): the coordinates are rounded to at most this times the size "
                        "of the interface (the diagonal of the bounding box of both contact parts); 0 "
                        "takes them as exact. Double round-off is always allowed for. No tolerance "
                        "depends on where the model lies.");
      prm.declare_entry("Close discretisation gaps", "true", Bool(),
                        "Node insertion: close the gaps between an inserted node and its partner that "
                        "come from two polygons approximating the same curve (below 1.5 times the "
                        "chord deviation of the edge, or below the coordinate precision), by moving "
                        "the inserted node onto its partner. Larger gaps (bodies apart, or surfaces of "
                        "different curvature as in Hertz contact) are kept. false keeps every gap.");
      prm.declare_entry("Pairing tolerance", "1e-8", Double(1e-14, 0.1),
                        "Finite strain ('Finite strain/Enabled = true', finite sliding): the pairs are made again "
                        "at the converged state of each step until the partners of every active pair are closer "
                        "than this fraction of the slave sub-edges at the pair.");
      prm.declare_entry("Maximum pairing passes", "12", Integer(1, 1000),
                        "Finite strain (finite sliding): at most this many passes (pairing and Newton solve) per "
                        "load step; a step that does not meet 'Pairing tolerance' then stops the program with the "
                        "offset of every pass.");
      prm.declare_entry("Maximum cutbacks", "4", Integer(0, 20),
                        "Finite strain (finite sliding): a load step whose Newton solve or pairing passes fail is "
                        "solved again from its start as two half steps, each cut again if it fails, down to "
                        "2^-(this) of the step; then the program stops naming the sub-step. 0: stop at once.");
      prm.declare_entry("Maximum active set iterations", "50", Integer(1),
                        "Iteration limit of the active set (per load step; with Coulomb friction, of the "
                        "semismooth Newton iteration over open/stick/slip).");
      prm.declare_entry("Active set acceleration", "true", Bool(),
                        "Correct the primal-dual active-set update where it crawls: a step that more than "
                        "doubles the set adds the deeper half of the penetrating pairs; a releasing step "
                        "also releases, next to each run of released pairs, the active pairs over the run's "
                        "length, until such a pair penetrates again. The solution is the same; false runs "
                        "the plain update.");
      prm.declare_entry("Globalized solve", "true", Bool(),
                        "Unilateral contact without Coulomb friction: when the active set cycles, reaches its "
                        "iteration limit or holds no equilibrium, solve again with the primal active-set method, "
                        "which converges whenever a solution exists and otherwise stops with 'No static "
                        "equilibrium' and the collapse mechanism that proves it (printed, and written as "
                        "<prefix>-mechanism.vtu and .svg). false: the active set's failure is the answer.");
      prm.leave_subsection();
    }

    // The contact problems' entries of 'Load steps' and 'Output'.
    void
    declare_steps_and_output(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection("Load steps");
      prm.declare_entry("Number of steps", "1", Integer(),
                        "Contact problems: number of quasi-static load steps. Step k solves at the time "
                        "t = k * 'Final time' / 'Number of steps' of the load and Dirichlet expressions; "
                        "Coulomb friction measures the slip against the previous step. With more than one "
                        "step every step writes its VTU and CSV files (base name + '-step-NNN') and a "
                        "ParaView time series (base name + '.pvd'). One body with 'Finite strain/Enabled = "
                        "true': the load steps of the Newton solve at the same times t; where no load or "
                        "Dirichlet expression uses t, step k applies k/N of the loads and Dirichlet values "
                        "instead; each step is written to base name + '-step-NNN.vtu' and the series base "
                        "name + '.pvd'. One body at small strain: the problem is linear and static, so it is "
                        "solved once at t = 'Final time' (a note says so when the number is above 1).");
      prm.declare_entry("Final time", "1", Double(),
                        "The time t of the last load step (> 0), in every problem: step k is at "
                        "t = k * 'Final time' / 'Number of steps' (the .pvd series and the JSON summary "
                        "carry these times). A one-body problem at small strain is solved at t = 'Final "
                        "time', with the exact solution compared there.");
      prm.leave_subsection();
      prm.enter_subsection("Output");
      prm.declare_entry("Write pictures", "true", Bool(),
                        "Contact problems: write SVG pictures of the deformed bodies (coloured by "
                        "sigma_yy, inserted nodes marked) and of the contact pressure.");
      prm.declare_entry("Write CSV", "true", Bool(),
                        "Contact problems: write the interface results as CSV.");
      prm.declare_entry("Moment point", "0, 0", Anything(),
                        "Contact problems: the point 'x, y' (two finite numbers) the moments are taken about, "
                        "counter-clockwise positive: the moment of each interface's contact forces on its slave "
                        "body (sum over the node pairs of (x - x0) x f, x the slave node) and of each support's "
                        "reaction on the bodies (sum over its constrained nodes of (x - x0) x R). A support is a "
                        "boundary id with Dirichlet data or a roller, or a point constraint; its reaction is the "
                        "internal force minus the applied loads and the contact forces at the DoFs it constrains. "
                        "Small strain: the positions of the undeformed configuration; the moments go to "
                        "<base name>-resultants.csv (column moment), <base name>-reactions.csv (step, time, support, "
                        "boundary_id, force_x, force_y, moment) and the JSON summary (interfaces.i.moment, "
                        "reactions.<support>.force_x, force_y, moment; with load steps also per step). Finite "
                        "sliding: the current positions x = X + u; per step to <base name>-history.csv (columns "
                        "force_x_i, force_y_i, moment_i per interface, reaction_x_<support>, reaction_y_<support>, "
                        "reaction_moment_<support> per support, load_x, load_y, load_moment of the applied loads), "
                        "<base name>-step-NNN-interface.csv (the node pairs) and the JSON summary "
                        "(steps.N.interfaces.i, steps.N.reactions.<support>, steps.N.loads). The supports are named "
                        "boundary_<id> and point_<k> (k: the index of the entry in 'Point constraints').");
      prm.leave_subsection();
    }
  } // namespace



  void
  ContactProblem::declare_parameters(dealii::ParameterHandler &prm, const unsigned int n_body_sections)
  {
    using namespace dealii::Patterns;
    prm.declare_entry("Number of bodies", "1", Integer(1, max_body_sections),
                      "Number of body sections. Body 0 is given by the sections 'Mesh' and "
                      "'Material', bodies 1, 2, ... by the sections 'Body 1', 'Body 2', ... (any number). "
                      "Each body's cells get the body index as material id. A mesh section with "
                      "'Parts as bodies = true' adds one body per part of its file.");
    declare_body_sections(prm, n_body_sections);
    declare_contact_section(prm);
    declare_steps_and_output(prm);
  }



  unsigned int
  ContactProblem::n_bodies(dealii::ParameterHandler &prm)
  {
    return prm.get_integer("Number of bodies");
  }



  bool
  ContactProblem::is_contact_problem(dealii::ParameterHandler &prm)
  {
    const unsigned int n = n_bodies(prm);
    if (n > 1)
      return true;
    prm.enter_subsection("Mesh");
    const bool parts = prm.get_bool("Parts as bodies");
    prm.leave_subsection();
    return parts;
  }



  unsigned int
  ContactProblem::body_sections(const std::string &filename)
  {
    // a plain scan of the lines (ParameterHandler parses the file later and
    // reports its errors): "subsection Body b" at the top level, "set Number
    // of bodies = n" and "include file", recursively. Each body b >= 1 of
    // 'Number of bodies' is described by its own section 'Body b', given
    // once: a section written twice (a copy whose number was not changed)
    // would merge into one body and leave another without a section, that
    // is the default mesh, and a missing section would do the same.
    unsigned int                 needed = default_body_sections;
    unsigned int                 largest = 0;
    std::vector<std::string>     files{filename};
    std::set<std::string>        seen;
    std::map<unsigned long, std::vector<std::string>> sections; // body -> "file:line" of each section
    // a body section read without a 'subsection Mesh' (nor an include
    // that may hold one): "file:line" of the section, by body
    std::map<unsigned long, std::string> without_mesh;
    long                         n_set = -1;                    // the last 'Number of bodies' given
    while (!files.empty() && seen.size() < 100)
      {
        const std::string file = files.back();
        files.pop_back();
        if (!seen.insert(file).second)
          continue;
        std::ifstream in(file);
        std::string   line;
        std::size_t   line_number = 0;
        int           depth       = 0;
        // the body section being read (its number, where it starts, and
        // whether it has a mesh section), if any
        long          body = -1;
        std::string   body_at;
        bool          body_has_mesh = false;
        while (std::getline(in, line))
          {
            ++line_number;
            std::istringstream words(line.substr(0, line.find('#')));
            std::string        w0, w1, w2;
            words >> w0 >> w1;
            if (w0 == "subsection")
              {
                if (depth == 0 && w1 == "Body" && (words >> w2))
                  {
                    unsigned long b = 0;
                    std::string   rest;
                    if (InputParsing::trim(w2).find_first_not_of("0123456789") == std::string::npos &&
                        w2.size() <= 6 && !(words >> rest))
                      {
                        b = std::stoul(w2);
                        sections[b].push_back(file + ":" + std::to_string(line_number));
                        body          = static_cast<long>(b);
                        body_at       = file + ":" + std::to_string(line_number);
                        body_has_mesh = false;
                      }
                    needed  = std::max<unsigned int>(needed, b + 1);
                    largest = std::max<unsigned int>(largest, b);
                  }
                else if (depth == 1 && body >= 0 && w1 == "Mesh")
                  body_has_mesh = true;
                ++depth;
              }
            else if (w0 == "end")
              {
                depth = std::max(depth - 1, 0);
                if (depth == 0 && body >= 0)
                  {
                    if (!body_has_mesh)
                      without_mesh.emplace(body, body_at);
                    body = -1;
                  }
              }
            else if (w0 == "set" && w1 == "Number" && depth == 0)
              {
                const auto eq = line.find('=');
                if (line.find("Number of bodies") != std::string::npos && eq != std::string::npos)
                  {
                    const std::string v = InputParsing::trim(line.substr(eq + 1, line.find('#') - eq - 1));
                    if (!v.empty() && v.size() <= 6 && v.find_first_not_of("0123456789") == std::string::npos)
                      {
                        needed = std::max<unsigned int>(needed, std::stoul(v));
                        n_set  = static_cast<long>(std::stoul(v));
                      }
                  }
              }
            else if (w0 == "include" && !w1.empty())
              {
                body_has_mesh = true; // (it may be in the file)
                const std::string dir = std::filesystem::path(file).parent_path().string();
                files.push_back(w1[0] == '/' || dir.empty() ? w1 : dir + "/" + w1);
              }
          }
      }
    AssertThrow(needed <= max_body_sections,
                dealii::ExcMessage("Parameter file '" + filename + "': it names section 'Body " +
                                   std::to_string(largest) + "' or sets 'Number of bodies' to " +
                                   std::to_string(needed) + "; a parameter file describes at most " +
                                   std::to_string(max_body_sections) +
                                   " bodies by sections. Read an assembly of more bodies from one mesh file, a "
                                   "body per material id ('Mesh/Parts as bodies = true')."));
    for (const auto &[b, where] : sections)
      AssertThrow(where.size() == 1,
                  dealii::ExcMessage("Parameter file '" + filename + "': section 'Body " + std::to_string(b) +
                                     "' is given " + std::to_string(where.size()) + " times (" + where[0] +
                                     " and " + where[1] +
                                     "). Each body has one section; was one of them meant for another body?"));
    // (the message, evaluated only when the check fails, names the first)
    AssertThrow(without_mesh.empty(),
                dealii::ExcMessage("Parameter file '" + filename + "': section 'Body " +
                                   std::to_string(without_mesh.begin()->first) + "' (" +
                                   without_mesh.begin()->second + ") has no 'subsection Mesh'. Without it body " +
                                   std::to_string(without_mesh.begin()->first) +
                                   " would silently be the default mesh (a Voronoi mesh of the unit square, "
                                   "overlapping body 0's default); give the body its mesh in the section."));
    if (n_set >= 2 && n_set <= static_cast<long>(max_body_sections))
      for (long b = 1; b < n_set; ++b)
        AssertThrow(sections.count(b) > 0,
                    dealii::ExcMessage("Parameter file '" + filename + "': 'Number of bodies' is " +
                                       std::to_string(n_set) + ", but there is no section 'Body " +
                                       std::to_string(b) + "' (body 0 is described by the top-level sections, body " +
                                       "b >= 1 by 'subsection Body b'). Without it body " + std::to_string(b) +
                                       " would silently be the default mesh; add the section, or lower "
                                       "'Number of bodies'."));
    return needed;
  }



  // The reading of a parameter file, one function per part of the file in
  // the order parse_parameters() calls them (the order of the checks, and
  // so of the first error a file meets, is that of the file's sections).
  struct ContactProblem::ParameterReader
  {
    ParameterReader(ContactProblem &p, dealii::ParameterHandler &prm)
      : p(p)
      , prm(prm)
      , n(n_bodies(prm))
      , opt(p.opt)
      , bodies(p.bodies)
      , bc(p.bc)
      , n_cycles(p.n_cycles)
      , prm_directory(p.prm_directory)
    {}

    /// The laws and names of a body's 'Part materials', by material id.
    struct PartMaterials
    {
      std::map<dealii::types::material_id, std::shared_ptr<const ConstitutiveLaw<2>>> laws;
      std::map<dealii::types::material_id, std::string>                              names;
    };

    void
    check_body_sections();
    void
    read_laws();
    std::shared_ptr<const ConstitutiveLaw<2>>
    body_law(const double E, const double nu) const;
    void
    read_body(const unsigned int b);
    PartMaterials
    read_part_materials(const Body &body, const std::string &prefix, const std::string &parts) const;
    void
    add_assembly(Body &body, const std::string &prefix, const PartMaterials &part_materials);
    void
    read_discretization();
    void
    read_contact();
    void
    read_contact_pairs();
    void
    read_contact_settings();
    void
    read_friction_tables();
    void
    check_finite_sliding_entries();
    void
    read_steps_solver_output();
    void
    check_run_size();

    ContactProblem           &p;
    dealii::ParameterHandler &prm;
    /// 'Number of bodies'.
    const unsigned int        n;
    ContactProblem::Options  &opt;
    std::vector<Body>        &bodies;
    BoundaryConditionParameters &bc;
    unsigned int             &n_cycles;
    const std::string        &prm_directory;
    /// 'Material/Model' and 'Material/Law' (the same for every body).
    ElasticMaterial::Model    model = ElasticMaterial::Model::plane_strain;
    MaterialLaws::Law         law   = "linear";
    /// The exact solution of body 0 (the default of the other bodies).
    std::string               exact0;
    /// Young's modulus and Poisson's ratio of body 0 (the default of the
    /// other bodies).
    std::pair<double, double> material0{1000., 0.3};
    /// The physical names of the bodies' gmsh files: boundary ids by name
    /// (with each body's boundary id offset) for the conditions and pairs,
    /// and the file each name came from.
    MeshIO::PhysicalNames              names;
    std::map<std::string, std::string> name_file;
  };



  void
  ContactProblem::parse_parameters(dealii::ParameterHandler &prm, const std::string &dir)
  {
    clear();
    prm_directory = dir;
    ParameterReader reader(*this, prm);
    reader.check_body_sections();
    reader.read_laws();
    for (unsigned int b = 0; b < reader.n; ++b)
      reader.read_body(b);
    reader.read_discretization();
    reader.read_contact();
    reader.check_finite_sliding_entries();
    reader.read_steps_solver_output();
    design.parse_parameters(prm);
    AssertThrow(!design.enabled() || !opt.finite_strain,
                dealii::ExcMessage("Design/Objective = " + design.objective +
                                   ": topology optimization is implemented for small strain; set "
                                   "'Finite strain/Enabled = false'."));
    AssertThrow(!design.enabled() || !opt.contact.is_coulomb(),
                dealii::ExcMessage("Design/Objective = " + design.objective +
                                   ": Coulomb friction is path-dependent and its system is not symmetric; design "
                                   "with 'Contact/Tangential' = multipliers, penalty or frictionless."));
    check_setup();
    reader.check_run_size();
    create_output_folder(opt.output_folder);
  }



  // 'Number of bodies' against the declared sections, and no section of a
  // body beyond that number.
  void
  ContactProblem::ParameterReader::check_body_sections()
  {
    {
      unsigned int declared = 1;
      while (prm.subsection_path_exists({"Body " + std::to_string(declared)}))
        ++declared;
      AssertThrow(n <= declared,
                  dealii::ExcMessage("Parameter 'Number of bodies' is " + std::to_string(n) + ", but only " +
                                     std::to_string(declared) + " body sections are declared; call "
                                     "ContactProblem::declare_parameters(prm, ContactProblem::body_sections(file)) "
                                     "(the program does)."));
    }
    // sections of bodies beyond the number of bodies would be ignored (one
    // listing of the changed entries for all sections: a file may declare
    // many)
    for (const auto &path : InputParsing::changed_entries(prm, ""))
      if (path.compare(0, 5, "Body ") == 0)
        {
          const std::string  section = path.substr(0, path.find('/'));
          const unsigned int b       = std::stoul(section.substr(5));
          if (b >= n)
            InputParsing::check_section_unused(prm, section,
                                               "'Number of bodies' is " + std::to_string(n) + ": section '" +
                                                 section + "' is read only with 'Number of bodies' at least " +
                                                 std::to_string(b + 1) + ".");
        }
  }



  // 'Convergence study', the material model and law, 'Finite strain'.
  void
  ContactProblem::ParameterReader::read_laws()
  {
    prm.enter_subsection("Convergence study");
    n_cycles = prm.get_integer("Refinement cycles");
    prm.leave_subsection();
    prm.enter_subsection("Material");
    model = ElasticMaterial::parse_model(prm.get("Model"));
    law   = MaterialLaws::parse(prm.get("Law"), "Material/Law");
    prm.leave_subsection();
    // 'Material/Law' applies to every body. With 'Finite strain/Enabled'
    // the problem is solved at finite strain with finite sliding
    // (run_finite_sliding()); else at small strain, where a hyperelastic law
    // is its linearization at F = I, the linear law of the same E and nu
    // (ElasticMaterial, built below)
    {
      FiniteStrainParameters finite_strain;
      finite_strain.parse_parameters(prm);
      opt.finite_strain = finite_strain.enabled;
      opt.newton        = finite_strain.solver;
      opt.pressure_load = finite_strain.pressure_load;
      AssertThrow(!finite_strain.enabled || MaterialLaws::is_hyperelastic(law),
                  dealii::ExcMessage("Parameter 'Finite strain/Enabled' is true, but 'Material/Law' is 'linear': "
                                     "finite strain needs a hyperelastic law ('neo-hooke' or "
                                     "'saint venant-kirchhoff')."));
      AssertThrow(!finite_strain.enabled || !finite_strain.has_monitor_point,
                  dealii::ExcMessage("Parameter 'Finite strain/Monitor point' is set, but contact problems do "
                                     "not use it: the history of the contact forces is written to "
                                     "<base name>-history.csv."));
      if (!finite_strain.enabled)
        InputParsing::check_section_unused(prm, "Finite strain",
                                           "'Finite strain/Enabled' is false: the program solves the contact "
                                           "problem at small strain, without the Newton controls of finite "
                                           "strain.");
    }
    if (MaterialLaws::is_hyperelastic(law) && !opt.finite_strain)
      p.pcout << "note: 'Material/Law = " << MaterialLaws::name(law)
                << "': contact problems are solved at small strain, with the law's linearization at F = I "
                   "(the linear law of the same E and nu) for every body."
                << std::endl;
  }



  // The law of a body of Young's modulus @p E and Poisson's ratio @p nu.
  std::shared_ptr<const ConstitutiveLaw<2>>
  ContactProblem::ParameterReader::body_law(const double E, const double nu) const
  {
    if (opt.finite_strain)
      return MaterialLaws::make_law(law, E, nu, model);
    return std::make_shared<const ElasticMaterial>(E, nu, model);
  }



  // Body section @p b: its mesh, the physical names of its file, its
  // material and exact solution; then the body itself or, for an assembly
  // file, one body per part.
  void
  ContactProblem::ParameterReader::read_body(const unsigned int b)
  {
    // body section b: the top-level sections for b = 0, 'Body b' else
    const std::string name   = (b == 0 ? std::string() : "Body " + std::to_string(b));
    const std::string prefix = (b == 0 ? std::string() : name + "/");
    if (b > 0)
      prm.enter_subsection(name);
    Body body;
    prm.enter_subsection("Mesh");
    body.mesh.parse_parameters(prm, prefix + "Mesh");
    prm.leave_subsection();
    body.mesh.load_physical_names(prm_directory);
    // a name that means two ids (two bodies from one file with an
    // offset) cannot be used; numbers can
    for (const auto &[key, id] : body.mesh.physical_names.boundary_ids)
      {
        if (names.unusable.count(key))
          continue;
        const auto it = names.boundary_ids.emplace(key, id);
        if (!it.second && it.first->second != id)
          {
            names.unusable[key] = "it is boundary id " + std::to_string(it.first->second) + " in '" +
                                  name_file[key] + "' and " + std::to_string(id) + " in '" +
                                  body.mesh.file_name + "' (" + prefix +
                                  "Mesh, with its 'Boundary id offset'); give the id by number";
            names.boundary_ids.erase(it.first);
          }
        name_file.emplace(key, body.mesh.file_name);
      }
    prm.enter_subsection("Material");
    // a body section without its own E or nu takes body 0's (the top-level
    // section's): a file that sets only 'Material' means every body
    double E  = material0.first;
    double nu = material0.second;
    if (b == 0)
      {
        E         = prm.get_double("Young's modulus");
        nu        = prm.get_double("Poisson's ratio");
        material0 = {E, nu};
      }
    else
      {
        const std::string e_text  = InputParsing::trim(prm.get("Young's modulus"));
        const std::string nu_text = InputParsing::trim(prm.get("Poisson's ratio"));
        if (!e_text.empty())
          E = InputParsing::parse_double(e_text, prefix + "Material/Young's modulus");
        if (!nu_text.empty())
          {
            nu = InputParsing::parse_double(nu_text, prefix + "Material/Poisson's ratio");
            InputParsing::check_range(nu, -1, 0.5, prefix + "Material/Poisson's ratio", true, true, "");
          }
      }
    const std::string parts = prm.get("Part materials");
    const std::string material_name = InputParsing::trim(prm.get("Name"));
    prm.leave_subsection();
    prm.enter_subsection("Exact solution");
    body.exact = prm.get("Displacement");
    prm.leave_subsection();
    if (b > 0)
      prm.leave_subsection();
    if (b == 0)
      exact0 = body.exact;
    else if (InputParsing::trim(body.exact).empty())
      body.exact = exact0;
    InputParsing::check_range(E, ElasticMaterial::min_youngs_modulus, ElasticMaterial::max_youngs_modulus,
                              prefix + "Material/Young's modulus", false, false,
                              "Choose units that bring E nearer to 1.");
    body.material = body_law(E, nu);
    check_material_name(material_name, "Parameter '" + prefix + "Material/Name'");
    body.material_name = material_name;
    const PartMaterials part_materials = read_part_materials(body, prefix, parts);
    if (!body.mesh.parts_as_bodies)
      {
        body.mesh.material_id = bodies.size();
        body.name             = "body " + std::to_string(bodies.size());
        body.modulus_parameter = prefix + "Material/Young's modulus";
        bodies.push_back(std::move(body));
        return;
      }
    add_assembly(body, prefix, part_materials);
  }



  // 'Part materials' of a body: material id : E : nu [: name].
  ContactProblem::ParameterReader::PartMaterials
  ContactProblem::ParameterReader::read_part_materials(const Body        &body,
                                                       const std::string &prefix,
                                                       const std::string &parts) const
  {
    PartMaterials out;
    auto         &part_laws  = out.laws;
    auto         &part_names = out.names;
    for (const auto &entry : InputParsing::split(parts, ';'))
      {
        const std::string what   = prefix + "Material/Part materials entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 3 || fields.size() == 4,
                    dealii::ExcMessage("Parameter '" + what +
                                       "': expected 'material id : E : nu' or 'material id : E : nu : name'."));
        const unsigned int id   = InputParsing::parse_id_or_name(
          fields[0], what, body.mesh.physical_names.material_ids, "material id",
          body.mesh.physical_names.list() + " (file '" + body.mesh.file_name + "')");
        const double       E_id = InputParsing::parse_double(fields[1], what);
        const double       nu_id = InputParsing::parse_double(fields[2], what);
        InputParsing::check_range(E_id, ElasticMaterial::min_youngs_modulus,
                                  ElasticMaterial::max_youngs_modulus, what + " (Young's modulus)", false,
                                  false, "Choose units that bring E nearer to 1.");
        InputParsing::check_range(nu_id, -1, 0.5, what + " (Poisson's ratio)", true, true);
        AssertThrow(part_laws.count(id) == 0,
                    dealii::ExcMessage("Parameter '" + what + "': material id " + std::to_string(id) +
                                       " is listed twice."));
        part_laws[id] = body_law(E_id, nu_id);
        if (fields.size() == 4)
          {
            part_names[id] = InputParsing::trim(fields[3]);
            check_material_name(part_names[id], "Parameter '" + what + "' (name)");
          }
      }
    AssertThrow(part_names.empty() || body.mesh.parts_as_bodies, dealii::ExcInternalError());
    AssertThrow(part_laws.empty() || body.mesh.parts_as_bodies,
                dealii::ExcMessage("Parameter '" + prefix + "Material/Part materials' is set, but '" + prefix +
                                   "Mesh/Parts as bodies' is false: parts are read only from a mesh file "
                                   "with 'Parts as bodies = true'."));
    return out;
  }



  // An assembly in one mesh file: each material id a body.
  void
  ContactProblem::ParameterReader::add_assembly(Body &body, const std::string &prefix, const PartMaterials &part_materials)
  {
    const auto &part_laws  = part_materials.laws;
    const auto &part_names = part_materials.names;
    AssertThrow(n_cycles == 1,
                dealii::ExcMessage("Parameter '" + prefix + "Mesh/Parts as bodies' is true: the parts are read "
                                   "once, so 'Convergence study/Refinement cycles' must be 1."));
    PolygonalMesh<2> assembly;
    body.mesh.create_mesh(assembly, 0, prm_directory);
    const auto ids = assembly.get_material_ids();
    for (const auto &law : part_laws)
      AssertThrow(std::binary_search(ids.begin(), ids.end(), law.first),
                  dealii::ExcMessage([&] {
                    std::string have;
                    for (const auto id : ids)
                      {
                        have += (have.empty() ? "" : ", ") + std::to_string(id);
                        for (const auto &[nm, i] : body.mesh.physical_names.material_ids)
                          if (i == id)
                            have += " ('" + nm + "')";
                      }
                    return "Parameter '" + prefix + "Material/Part materials' gives material id " +
                           std::to_string(law.first) + ", which no cell of the mesh file '" +
                           body.mesh.file_name + "' has; the material ids of the file are " + have +
                           ". Give the parts by these ids or by their physical names.";
                  }()));
    const auto added = p.add_parts(assembly, *body.material, part_laws, 0);
    for (unsigned int i = 0; i < added.size(); ++i)
      {
        bodies[added[i]].exact = body.exact;
        bodies[added[i]].modulus_parameter =
          prefix + (part_laws.count(ids[i]) ? "Material/Part materials" : "Material/Young's modulus");
        const auto name        = part_names.find(ids[i]);
        bodies[added[i]].material_name = (name != part_names.end() ? name->second : body.material_name);
        bodies[added[i]].name  = "body " + std::to_string(added[i]) + " (material id " +
                                std::to_string(ids[i]) + " of " + body.mesh.file_name + ")";
      }
    // (every process parses the file; process 0 prints)
    p.pcout << "  " << prefix << "Mesh: " << added.size() << " parts of '" << body.mesh.file_name
              << "' are bodies " << added.front() << " to " << added.back() << std::endl;
  }



  // 'Discretization' and the boundary conditions.
  void
  ContactProblem::ParameterReader::read_discretization()
  {
    prm.enter_subsection("Discretization");
    opt.degree               = prm.get_integer("Order");
    opt.stabilization_factor = prm.get_double("Stabilization factor");
    opt.stabilization        = InputParsing::parse_stabilization(prm.get("Stabilization"));
    prm.leave_subsection();
    bc.set_physical_names(names);
    bc.parse_parameters(prm);
  }



  // Section 'Contact': the pairs, the contact and insertion settings, the
  // friction tables; a warning for a penalty no model uses.
  void
  ContactProblem::ParameterReader::read_contact()
  {
    prm.enter_subsection("Contact");
    read_contact_pairs();
    read_contact_settings();
    read_friction_tables();
    const std::string tangential_name = prm.get("Tangential");
    prm.leave_subsection();
    const auto &cs = opt.contact;
    if (cs.tangential != ContactSettings::Tangential::penalty &&
        cs.tangential != ContactSettings::Tangential::coulomb_penalty)
      for (const auto &e : InputParsing::changed_entries(prm, "Contact"))
        if (e == "Contact/Penalty" || e == "Contact/Penalty factor")
          p.pcout << "warning: the parameter file sets '" << e << "', but 'Contact/Tangential' is '"
                    << tangential_name << "', which uses no stick penalty; the setting has no effect." << std::endl;
  }



  // 'Contact/Pairs': "master : slave [: mu]; ..." and "auto".
  void
  ContactProblem::ParameterReader::read_contact_pairs()
  {
    for (const auto &entry : InputParsing::split(prm.get("Pairs"), ';'))
      {
        if (InputParsing::trim(entry) == "auto")
          {
            AssertThrow(!opt.detect_pairs,
                        dealii::ExcMessage("Parameter 'Contact/Pairs': 'auto' is given twice."));
            opt.detect_pairs = true;
            continue;
          }
        const std::string name   = "Contact/Pairs entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 2 || fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + name +
                                       "': expected 'master id : slave id', 'master id : slave id : "
                                       "friction coefficient', or 'auto' (the interfaces found by contact "
                                       "detection)."));
        double mu = -1;
        if (fields.size() == 3)
          {
            mu = InputParsing::parse_double(fields[2], name);
            InputParsing::check_range(mu, 0, 1e6, name + " (friction coefficient)", false, false,
                                      "The Coulomb friction coefficient is a number >= 0.");
          }
        const unsigned int a =
          InputParsing::parse_id_or_name(fields[0], name, names.boundary_ids, "boundary id", names.list());
        const unsigned int s =
          InputParsing::parse_id_or_name(fields[1], name, names.boundary_ids, "boundary id", names.list());
        AssertThrow(a < 255 && s < 255 && a != s,
                    dealii::ExcMessage("Parameter '" + name + "': two different boundary ids below 255 expected."));
        p.add_contact_pair(a, s, mu, "Parameter '" + name + "'");
      }
  }



  // The contact model, its limits and the node insertion and detection
  // settings.
  void
  ContactProblem::ParameterReader::read_contact_settings()
  {
    auto &cs          = opt.contact;
    cs.normal         = ContactSettings::parse_normal(prm.get("Normal"));
    cs.tangential     = ContactSettings::parse_tangential(prm.get("Tangential"));
    cs.friction_coefficient      = prm.get_double("Friction coefficient");
    cs.penalty                   = prm.get_double("Penalty");
    cs.penalty_factor            = prm.get_double("Penalty factor");
    cs.max_active_set_iterations = prm.get_integer("Maximum active set iterations");
    cs.accelerate_active_set     = prm.get_bool("Active set acceleration");
    cs.globalize                 = prm.get_bool("Globalized solve");
    opt.insertion.merge_fraction            = prm.get_double("Merge fraction");
    opt.insertion.search_distance           = prm.get_double("Search distance");
    {
      const std::string precision = InputParsing::trim(prm.get("Coordinate precision"));
      opt.insertion.coordinate_precision =
        (precision == "auto" ? NodeInsertion::Settings::detect_precision :
                               InputParsing::parse_double(precision, "Contact/Coordinate precision"));
    }
    opt.insertion.close_discretisation_gaps = prm.get_bool("Close discretisation gaps");
    opt.detection.distance                  = prm.get_double("Detection distance");
    opt.detection.max_angle                 = prm.get_double("Detection angle");
    opt.detection.merge_fraction            = opt.insertion.merge_fraction;
    opt.pairing_tolerance                   = prm.get_double("Pairing tolerance");
    opt.max_pairing_passes                  = prm.get_integer("Maximum pairing passes");
    opt.max_cutbacks                        = prm.get_integer("Maximum cutbacks");
  }



  // 'Contact/Friction between bodies' and 'Friction between materials'.
  void
  ContactProblem::ParameterReader::read_friction_tables()
  {
    for (const auto &entry : InputParsing::split(prm.get("Friction between bodies"), ';'))
      {
        const std::string what   = "Contact/Friction between bodies entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + what + "': expected 'body a : body b : mu' (body "
                                       "indices or '*')."));
        unsigned int body[2];
        for (unsigned int k = 0; k < 2; ++k)
          {
            body[k] = (InputParsing::trim(fields[k]) == "*") ? dealii::numbers::invalid_unsigned_int :
                                                                InputParsing::parse_unsigned(fields[k], what);
            AssertThrow(body[k] == dealii::numbers::invalid_unsigned_int || body[k] < bodies.size(),
                        dealii::ExcMessage("Parameter '" + what + "': there is no body " +
                                           std::to_string(body[k]) + " (the bodies are 0 to " +
                                           std::to_string(bodies.size() - 1) + ")."));
          }
        const double mu = InputParsing::parse_double(fields[2], what);
        InputParsing::check_range(mu, 0, 1e6, what + " (friction coefficient)", false, false,
                                  "The Coulomb friction coefficient is a number >= 0.");
        p.set_friction_coefficient(body[0], body[1], mu);
      }
    for (const auto &entry : InputParsing::split(prm.get("Friction between materials"), ';'))
      {
        const std::string what   = "Contact/Friction between materials entry '" + entry + "'";
        const auto        fields = InputParsing::split(entry, ':', true);
        AssertThrow(fields.size() == 3,
                    dealii::ExcMessage("Parameter '" + what + "': expected 'name a : name b : mu' (material "
                                       "names from 'Material/Name' or 'Part materials', or '*')."));
        std::string name[2];
        for (unsigned int k = 0; k < 2; ++k)
          {
            name[k] = InputParsing::trim(fields[k]);
            if (name[k] != "*")
              check_material_name(name[k], "Parameter '" + what + "'");
          }
        const double mu = InputParsing::parse_double(fields[2], what);
        InputParsing::check_range(mu, 0, 1e6, what + " (friction coefficient)", false, false,
                                  "The Coulomb friction coefficient is a number >= 0.");
        p.set_friction_coefficient(name[0], name[1], mu);
      }
  }



  // Finite sliding reads the pairs, the normal and tangential rule, the
  // friction coefficient, the pairing controls, the cutbacks and the
  // search distance; any other setting of the small-strain contact loop
  // or of node insertion in the reference configuration is refused by
  // name (after the contact rule: a rule finite sliding does not take is
  // named first, by run_finite_sliding()).
  void
  ContactProblem::ParameterReader::check_finite_sliding_entries()
  {
    const auto &cs = opt.contact;
    const bool sliding_rule =
      cs.normal == ContactSettings::Normal::tied ?
        cs.tangential == ContactSettings::Tangential::multipliers :
        (cs.tangential == ContactSettings::Tangential::frictionless ||
         cs.tangential == ContactSettings::Tangential::coulomb);
    if (opt.finite_strain && sliding_rule)
      {
        static const std::map<std::string, std::string> unread = {
          {"Contact/Merge fraction", "node insertion at finite strain merges only nodes within 1e-9 of an edge"},
          {"Contact/Coordinate precision", "finite sliding keeps every gap (no gap closing)"},
          {"Contact/Close discretisation gaps", "finite sliding keeps every gap (no gap closing)"},
          {"Contact/Maximum active set iterations",
           "the contact conditions are part of the Newton iteration ('Finite strain/Maximum Newton iterations')"},
          {"Contact/Active set acceleration",
           "the contact conditions are part of the Newton iteration ('Finite strain/Maximum Newton iterations')"},
          {"Contact/Globalized solve",
           "the contact conditions are part of the Newton iteration ('Finite strain/Maximum Newton iterations')"},
          {"Contact/Penalty", "finite sliding has no stick penalty (friction by Lagrange multipliers)"},
          {"Contact/Penalty factor", "finite sliding has no stick penalty (friction by Lagrange multipliers)"},
          {"Discretization/Stabilization factor", "finite sliding scales the stabilization by the tangent, with "
                                                  "the factor 1"},
        };
        std::vector<std::string> set = InputParsing::changed_entries(prm, "Contact");
        for (const auto &e : InputParsing::changed_entries(prm, "Discretization"))
          set.push_back(e);
        for (const auto &e : InputParsing::changed_entries(prm, "Solver"))
          set.push_back(e);
        for (const auto &e : set)
          {
            const auto it = unread.find(e);
            const bool solver = e.compare(0, 7, "Solver/") == 0;
            AssertThrow(it == unread.end() && !solver,
                        dealii::ExcMessage(
                          "Parameter '" + e + "' is set, but 'Finite strain/Enabled' is true (finite sliding), which "
                          "does not read it: " +
                          (solver ? std::string("every Newton update is solved by UMFPACK") : it->second) +
                          ". Remove the entry, or set 'Finite strain/Enabled = false' (small strain)."));
          }
      }
  }



  // 'Load steps', 'Solver' and 'Output'.
  void
  ContactProblem::ParameterReader::read_steps_solver_output()
  {
    prm.enter_subsection("Load steps");
    {
      const long steps = prm.get_integer("Number of steps");
      InputParsing::check_number_of_load_steps(steps);
      opt.n_load_steps = steps;
    }
    opt.final_time = prm.get_double("Final time");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    opt.solver = prm.get("Type");
    // 'automatic' is resolved in setup_system(), when the size is known
    opt.solver_tolerance      = prm.get_double("Relative tolerance");
    opt.solver_max_iterations = prm.get_integer("Maximum iterations");
    opt.warm_start            = prm.get_bool("Warm start");
    opt.solver_preconditioner = prm.get("Preconditioner");
    AssertThrow(opt.solver_preconditioner != "p-multigrid" || PMultigrid::applies_to(VEMElementData(opt.degree)),
                dealii::ExcMessage("Solver/Preconditioner = p-multigrid needs Discretization/Order = 2 (the "
                                   "coarse level is the order-1 space on the same polygons)."));
    prm.leave_subsection();

    prm.enter_subsection("Output");
    opt.output_folder  = prm.get("Folder");
    opt.base_name      = prm.get("Base name");
    opt.write_vtu      = prm.get_bool("Write VTU");
    opt.write_json     = prm.get_bool("Write JSON");
    opt.write_pictures = prm.get_bool("Write pictures");
    opt.write_csv      = prm.get_bool("Write CSV");
    {
      const std::string name  = "Output/Moment point";
      const auto        parts = InputParsing::split(prm.get("Moment point"), ',');
      AssertThrow(parts.size() == 2, dealii::ExcMessage("Parameter '" + name + "': expected 'x, y', got '" +
                                                        prm.get("Moment point") + "'."));
      // (parse_double refuses what is not a finite number, naming the entry)
      for (unsigned int c = 0; c < 2; ++c)
        opt.moment_point[c] = InputParsing::parse_double(parts[c], name);
    }
    prm.leave_subsection();
  }



  // The estimated size of the run against the limits.
  void
  ContactProblem::ParameterReader::check_run_size()
  {
    {
      // (the parts of an assembly file are read already)
      std::vector<const MeshParameters *> meshes;
      for (const auto &b : bodies)
        if (b.given == nullptr)
          meshes.push_back(&b.mesh);
      InputParsing::check_run_size(meshes, n_cycles, opt.degree, prm.get_bool("Allow large runs"), prm_directory,
                                   opt.solver == "UMFPACK" || opt.solver == "KLU" ?
                                     InputParsing::SolverKind::direct :
                                     InputParsing::SolverKind::iterative,
                                   prm.get_double("Memory limit"));
    }
  }
} // namespace dealvem
