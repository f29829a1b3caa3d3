// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
#ifndef dealvem_app_mesh_parameters_h
#define dealvem_app_mesh_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <dealvem/mesh/mesh_io.h>
#include <dealvem/mesh/polygonal_mesh.h>
#include <dealvem/mesh/gear_rack.h>
#include <dealvem/mesh/spur_gear.h>

#include <string>

namespace dealvem
{
  /**
   * The mesh source of one body, as a parameter-file section:
   * a generator (structured quads or triangles, perturbed quads,
   * centroidal Voronoi, the non-convex family) on a rectangle, a spur
   * gear or a sector of one (subsection 'Gear': SpurGear and
   * PolygonalMeshGenerators::spur_gear()), a gear rack (subsection
   * 'Rack': GearRack and PolygonalMeshGenerators::gear_rack()), a polygon
   * mesh file (legacy VTK, see MeshIO), a gmsh .msh file (MeshIO::read_msh:
   * physical curves as boundary ids, physical surfaces as material ids, both
   * nameable in the parameter file by their physical names), or any other
   * file deal.II's GridIn reads (UCD, ...).
   */
  struct MeshParameters
  {
    /// 'Type': a generator name, "vtk file" or "gridin file".
    std::string      type = "voronoi";
    /// 'Lower left corner' of the generators' rectangle.
    dealii::Point<2> lower_left{0., 0.};
    /// 'Upper right corner' of the generators' rectangle.
    dealii::Point<2> upper_right{1., 1.};
    /// 'Subdivisions' nx, ny of the structured, perturbed and non-convex
    /// generators (on level 0; each refinement doubles them).
    unsigned int     nx = 8;
    unsigned int     ny = 8; ///< see nx
    /// 'Number of cells' of the Voronoi generator (level 0; each
    /// refinement multiplies it by four).
    unsigned int     n_cells = 64;
    /// 'Lloyd iterations' of the Voronoi generator.
    unsigned int     lloyd_iterations = 20;
    /// 'Perturbation' of "perturbed quads", relative to the cell size.
    double           perturbation = 0.2;
    /// 'Non-convex depth' of the reflex vertex of "nonconvex" cells.
    double           nonconvex_depth = 0.3;
    /// 'Seed' of the random generators.
    unsigned int     seed = 1;
    /// 'File name' of the file types, relative to the parameter file.
    std::string      file_name;
    /// 'Material id' given to the cells of a generated mesh (a file keeps
    /// its own).
    unsigned int     material_id = 0;
    /// 'Material id' given as the name of a physical surface (resolved by
    /// load_physical_names()); empty for a number.
    std::string      material_name;
    /// The physical names of the mesh file (a gmsh file; empty otherwise),
    /// boundary ids with the boundary id offset added: set by
    /// load_physical_names().
    MeshIO::PhysicalNames physical_names;
    /// The section name given to parse_parameters(), for messages.
    std::string      section = "Mesh";
    /// 'Boundary id offset' added to every boundary id.
    unsigned int     boundary_id_offset = 0;
    /// 'Parts as bodies': every material id of a mesh file is a body of
    /// its own (ContactProblem); a 'gridin file' then gets separate
    /// vertices per material id (see PolygonalMeshGenerators::from_triangulation()).
    bool             parts_as_bodies = false;
    /// 'Shift' applied to the vertices, after the transformation.
    dealii::Point<2> shift{0., 0.};
    /// Vertex map "x', y'" in x, y (muparser); empty for none.
    std::string      transformation;
    /// Subsection 'Gear' of Type = "spur gear": the gear's data (angles
    /// converted to radians).
    SpurGear::Parameters gear;
    /// Subsection 'Gear': the part meshed and the grading (each refinement
    /// of a convergence study adds a global refinement).
    PolygonalMeshGenerators::GearMeshSettings gear_mesh;
    /// Subsection 'Rack' of Type = "gear rack": the rack's data (angles
    /// converted to radians).
    GearRack::Parameters rack;
    /// Subsection 'Rack': the grading (each refinement of a convergence
    /// study adds a global refinement).
    PolygonalMeshGenerators::RackMeshSettings rack_mesh;

    /// Declare the entries in the current subsection of @p prm.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// Read them back; @p section is used in error messages.
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &section);

    /**
     * Build the mesh. @p refinement > 0 refines generated meshes
     * (subdivisions times 2^refinement, Voronoi cells times 4^refinement);
     * files cannot be refined (AssertThrow). Relative file names are taken
     * relative to @p base_directory. All cells of generated meshes get
     * material_id; every boundary id is increased by boundary_id_offset
     * (so that several bodies can use the generators' ids 0..3 without
     * clashing), the vertices are mapped by the transformation (edges stay
     * straight; the result is validated) and the mesh is moved by shift.
     */
    void
    create_mesh(PolygonalMesh<2>  &mesh,
                const unsigned int refinement,
                const std::string &base_directory = "") const;

    /// Add @p offset to the boundary id of every boundary edge of @p mesh
    /// (an id beyond 254 is an error naming @p what).
    static void
    shift_boundary_ids(PolygonalMesh<2>  &mesh,
                       const unsigned int offset,
                       const std::string &what = "Boundary id offset");

    /// Read the physical names of the mesh file (gmsh files; relative
    /// names relative to @p base_directory; with '{cycle}' the file of cycle
    /// 0) into physical_names and resolve a 'Material id' given by name.
    /// A missing file leaves the names empty (create_mesh() reports it).
    void
    load_physical_names(const std::string &base_directory);

    /// Read subsection 'Gear' (and check the gear when Type = "spur gear",
    /// naming the section in the message).
    void
    parse_gear_parameters(dealii::ParameterHandler &prm);

    /// Read subsection 'Rack' (and check the rack when Type = "gear rack",
    /// naming the section in the message).
    void
    parse_rack_parameters(dealii::ParameterHandler &prm);

    /// A one-line description, e.g. "voronoi, 64 cells, 20 Lloyd iterations".
    std::string
    description() const;
  };
} // namespace dealvem

#endif
