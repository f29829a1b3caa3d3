// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A block mesh of a spur gear: per half tooth, blocks between the tooth
// axis and the outline (the tip and flank blocks, the fillet block), two
// root blocks under the fillet and the space, and a rim of two columns down
// to the bore. The outline faces carry a chart manifold whose chart is the
// gear's outline coordinate, the circular faces a polar manifold, the cells
// transfinite interpolation.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <dealvem/base/number_string.h>
#include <dealvem/mesh/generators.h>
#include <dealvem/mesh/spur_gear.h>

#include <cmath>
#include <functional>
#include <memory>

namespace dealvem
{
  using internal::number_string;

  namespace
  {

    dealii::Point<2>
    polar(const double radius, const double angle)
    {
      return dealii::Point<2>(radius * std::cos(angle), radius * std::sin(angle));
    }

    /// The gear's outline as a deal.II chart manifold: chart coordinate =
    /// SpurGear's outline coordinate, periodic over the whole gear.
    class GearOutlineManifold : public dealii::ChartManifold<2, 2, 1>
    {
    public:
      explicit GearOutlineManifold(const std::shared_ptr<const SpurGear> &gear)
        : dealii::ChartManifold<2, 2, 1>(dealii::Tensor<1, 1>({gear->outline_pitch_length() * gear->n_teeth()}))
        , gear(gear)
      {}

      std::unique_ptr<dealii::Manifold<2, 2>>
      clone() const override
      {
        return std::make_unique<GearOutlineManifold>(gear);
      }

      dealii::Point<1>
      pull_back(const dealii::Point<2> &space_point) const override
      {
        return dealii::Point<1>(gear->outline_coordinate(space_point));
      }

      dealii::Point<2>
      push_forward(const dealii::Point<1> &chart_point) const override
      {
        return gear->outline_point(chart_point[0]);
      }

      dealii::DerivativeForm<1, 1, 2>
      push_forward_gradient(const dealii::Point<1> &chart_point) const override
      {
        const dealii::Tensor<1, 2>      t = gear->outline_tangent(chart_point[0]);
        dealii::DerivativeForm<1, 1, 2> grad;
        grad[0][0] = t[0];
        grad[1][0] = t[1];
        return grad;
      }

    private:
      std::shared_ptr<const SpurGear> gear;
    };

    /// The block mesh's points and quadrilaterals (counter-clockwise).
    struct BlockMesh
    {
      std::vector<dealii::Point<2>>    points;
      std::vector<dealii::CellData<2>> cells;

      unsigned int
      add(const dealii::Point<2> &p)
      {
        points.push_back(p);
        return points.size() - 1;
      }

      /// A quadrilateral from its corners in counter-clockwise order.
      void
      quad(const std::array<dealii::Point<2>, 4> &ccw)
      {
        dealii::CellData<2> cell;
        // deal.II numbers a quadrilateral's vertices lexicographically
        cell.vertices[0] = add(ccw[0]);
        cell.vertices[1] = add(ccw[1]);
        cell.vertices[2] = add(ccw[3]);
        cell.vertices[3] = add(ccw[2]);
        cell.material_id = 0;
        cells.push_back(cell);
      }
    };

    /**
     * half_tooth_blocks() for an internal gear: the tooth points toward the
     * centre (its tip at the smallest radius), the root blocks and the rim
     * lie outside the root circle. @p flank holds the flank's points from
     * the tip corner to the form point, the other points are those of
     * half_tooth_blocks().
     */
    std::vector<std::array<dealii::Point<2>, 4>>
    internal_half_tooth_blocks(const SpurGear                      &gear,
                               const std::vector<dealii::Point<2>> &flank,
                               const dealii::Point<2>              &tip_axis,
                               const dealii::Point<2>              &form,
                               const dealii::Point<2>              &fillet_mid,
                               const double                         phi_mid)
    {
      const double                  tau = gear.angular_pitch() / 2;
      const unsigned int            n   = flank.size() - 1;
      std::vector<dealii::Point<2>> axis(n + 1);
      for (unsigned int i = 0; i <= n; ++i)
        axis[i] = dealii::Point<2>(flank[i][0], 0.);
      axis[0] = tip_axis;
      // the root blocks reach out to r_m: the space's half width beyond the root circle
      const double space_width = gear.root_radius() * (tau - phi_mid);
      const double r_m         = std::max(gear.root_radius() + space_width, fillet_mid[0] + 0.5 * space_width);
      AssertThrow(r_m < 0.95 * gear.body_radius(),
                  dealii::ExcMessage("spur_gear(): the rim radius " + number_string(gear.body_radius()) +
                                     " leaves no rim outside the teeth (the rim starts at radius " +
                                     number_string(r_m) + "); choose a larger rim radius."));
      const dealii::Point<2> fillet_axis(fillet_mid[0], 0.), rim_axis(r_m, 0.);
      const dealii::Point<2> space = polar(gear.root_radius(), tau), rim_mid = polar(r_m, phi_mid),
                             rim_space = polar(r_m, tau);
      std::vector<std::array<dealii::Point<2>, 4>> blocks;
      for (unsigned int i = 0; i < n; ++i)
        blocks.push_back({{axis[i], axis[i + 1], flank[i + 1], flank[i]}});
      blocks.push_back({{axis[n], fillet_axis, fillet_mid, form}});
      blocks.push_back({{fillet_axis, rim_axis, rim_mid, fillet_mid}});
      blocks.push_back({{fillet_mid, rim_mid, rim_space, space}});
      // rim: layers about as thick as the columns are wide, out to the rim radius
      const double       R        = gear.body_radius();
      const double       ratio    = 1. + 0.75 * tau;
      const unsigned int n_layers = std::max(1, static_cast<int>(std::ceil(std::log(R / r_m) / std::log(ratio))));
      for (unsigned int l = 0; l < n_layers; ++l)
        {
          const double inner = r_m * std::pow(R / r_m, double(l) / n_layers);
          const double outer = (l + 1 == n_layers ? R : r_m * std::pow(R / r_m, double(l + 1) / n_layers));
          blocks.push_back({{polar(inner, 0.), polar(outer, 0.), polar(outer, phi_mid), polar(inner, phi_mid)}});
          blocks.push_back({{polar(inner, phi_mid), polar(outer, phi_mid), polar(outer, tau), polar(inner, tau)}});
        }
      return blocks;
    }



    /// The blocks of one half tooth in the tooth's frame (axis along +x,
    /// the upper half), given by their corners; mirrored for the lower half.
    std::vector<std::array<dealii::Point<2>, 4>>
    half_tooth_blocks(const SpurGear &gear, unsigned int &n_flank_blocks)
    {
      const auto  &starts = gear.piece_starts();
      const double tau    = gear.angular_pitch() / 2;
      // the tooth frame of tooth 0: undo the gear's placement
      const auto local = [&](const double s) {
        const dealii::Tensor<1, 2> p = gear.outline_point(s) - gear.parameters().center;
        const double               a = -gear.parameters().rotation;
        return dealii::Point<2>(std::cos(a) * p[0] - std::sin(a) * p[1], std::sin(a) * p[0] + std::cos(a) * p[1]);
      };
      const dealii::Point<2> tip_axis = local(0.5 * (starts[3] + starts[4]));
      const dealii::Point<2> form     = local(starts[5]);
      // the fillet's middle (in its outline coordinate)
      const dealii::Point<2> fillet_mid = local(0.5 * (starts[5] + starts[6]));
      const dealii::Point<2> space      = polar(gear.root_radius(), tau);
      const double           phi_mid    = std::atan2(fillet_mid[1], fillet_mid[0]);

      // flank blocks about as tall as the half tooth is wide at the reference circle
      const double half_width = gear.reference_radius() * gear.flank_half_angle(gear.reference_radius());
      n_flank_blocks = std::max(1, static_cast<int>(std::lround((starts[5] - starts[4]) / (1.2 * half_width))));
      std::vector<dealii::Point<2>> flank(n_flank_blocks + 1), axis(n_flank_blocks + 1);
      for (unsigned int i = 0; i <= n_flank_blocks; ++i)
        {
          flank[i] = local(starts[4] + (starts[5] - starts[4]) * i / n_flank_blocks);
          axis[i]  = dealii::Point<2>(flank[i][0], 0.);
        }
      axis[0] = tip_axis;

      if (gear.is_internal())
        return internal_half_tooth_blocks(gear, flank, tip_axis, form, fillet_mid, phi_mid);

      // the root blocks reach down to r_m: the space's half width below the root circle
      const double space_width = gear.root_radius() * (tau - phi_mid);
      const double r_m         = std::min(gear.root_radius() - space_width, fillet_mid[0] - 0.5 * space_width);
      AssertThrow(r_m > 1.05 * gear.parameters().bore_radius,
                  dealii::ExcMessage("spur_gear(): the bore radius " + number_string(gear.parameters().bore_radius) +
                                     " leaves no rim under the teeth (the rim starts at radius " + number_string(r_m) +
                                     "); choose a smaller bore."));
      const dealii::Point<2> fillet_axis(fillet_mid[0], 0.), rim_axis(r_m, 0.);
      const dealii::Point<2> rim_mid = polar(r_m, phi_mid), rim_space = polar(r_m, tau);

      std::vector<std::array<dealii::Point<2>, 4>> blocks;
      for (unsigned int i = 0; i < n_flank_blocks; ++i)
        blocks.push_back({{axis[i + 1], axis[i], flank[i], flank[i + 1]}});
      blocks.push_back({{fillet_axis, axis[n_flank_blocks], form, fillet_mid}});
      blocks.push_back({{rim_axis, fillet_axis, fillet_mid, rim_mid}});
      blocks.push_back({{rim_mid, fillet_mid, space, rim_space}});

      // rim: layers about as thick as the columns are wide, down to the bore
      const double       r_bore   = gear.parameters().bore_radius;
      const double       ratio    = 1. - 0.75 * tau;
      const unsigned int n_layers = std::max(1, static_cast<int>(std::ceil(std::log(r_bore / r_m) / std::log(ratio))));
      for (unsigned int l = 0; l < n_layers; ++l)
        {
          const double outer = r_m * std::pow(r_bore / r_m, double(l) / n_layers);
          const double inner = (l + 1 == n_layers ? r_bore : r_m * std::pow(r_bore / r_m, double(l + 1) / n_layers));
          blocks.push_back({{polar(inner, 0.), polar(outer, 0.), polar(outer, phi_mid), polar(inner, phi_mid)}});
          blocks.push_back({{polar(inner, phi_mid), polar(outer, phi_mid), polar(outer, tau), polar(inner, tau)}});
        }
      return blocks;
    }


    /// The quadrilateral blocks of teeth [@p first, @p first + @p n): the
    /// half-tooth blocks of half_tooth_blocks(), placed at each tooth's axis
    /// and mirrored for the clockwise half.
    BlockMesh
    tooth_blocks(const SpurGear &gear, const unsigned int first, const unsigned int n)
    {
      unsigned int n_flank_blocks = 0;
      const auto   half           = half_tooth_blocks(gear, n_flank_blocks);
      const auto  &prm            = gear.parameters();
      const double tau            = gear.angular_pitch() / 2;

      BlockMesh blocks;
      for (unsigned int k = first; k < first + n; ++k)
        {
          const double axis  = prm.rotation + 2 * tau * k;
          const auto   place = [&](const dealii::Point<2> &p, const bool mirror) {
            const dealii::Point<2> q(p[0], mirror ? -p[1] : p[1]);
            return prm.center + dealii::Tensor<1, 2>({std::cos(axis) * q[0] - std::sin(axis) * q[1],
                                                      std::sin(axis) * q[0] + std::cos(axis) * q[1]});
          };
          for (const auto &b : half)
            {
              blocks.quad({{place(b[0], false), place(b[1], false), place(b[2], false), place(b[3], false)}});
              // the mirror image reverses the orientation
              blocks.quad({{place(b[3], true), place(b[2], true), place(b[1], true), place(b[0], true)}});
            }
        }
      return blocks;
    }



    /**
     * Boundary ids and manifold ids of the coarse triangulation of teeth
     * [@p first, @p first + @p n): 1 the outline (manifold 1), 0 the bore (manifold 2),
     * 2 and 3 the sector sides; inner arcs about the centre get manifold 2
     * too, everything else is flat.
     */
    void
    set_gear_ids(dealii::Triangulation<2, 2>           &tria,
                 const std::shared_ptr<const SpurGear> &gear,
                 const unsigned int                     first,
                 const unsigned int                     n)
    {
      const auto  &prm = gear->parameters();
      const double tau = gear->angular_pitch() / 2;
      // manifolds: 1 the outline, 2 circles about the centre; the cells are
      // flat: deal.II places a refined quadrilateral's centre by the weights
      // -1/4 on the vertices and 1/2 on the (curved) face midpoints, the
      // transfinite interpolation at the centre (deal.II's
      // TransfiniteInterpolationManifold fails to pull back the tip corners)
      const double scale     = gear->tip_radius();
      const auto   on_circle = [&](const dealii::Point<2> &a, const dealii::Point<2> &b) {
        return std::abs(a.distance(prm.center) - b.distance(prm.center)) < 1e-9 * scale;
      };
      for (const auto &cell : tria.active_cell_iterators())
        {
          cell->set_manifold_id(dealii::numbers::flat_manifold_id);
          for (const auto f : cell->face_indices())
            {
              const auto face = cell->face(f);
              face->set_manifold_id(dealii::numbers::flat_manifold_id);
              const dealii::Point<2> a = face->vertex(0), b = face->vertex(1);
              if (face->at_boundary())
                {
                  if (gear->distance_to_outline(a) < 1e-9 * scale && gear->distance_to_outline(b) < 1e-9 * scale &&
                      !(on_circle(a, b) && std::abs(a.distance(prm.center) - gear->body_radius()) < 1e-9 * scale))
                    {
                      face->set_boundary_id(1);
                      face->set_manifold_id(1);
                    }
                  else if (on_circle(a, b) && std::abs(a.distance(prm.center) - gear->body_radius()) < 1e-9 * scale)
                    {
                      face->set_boundary_id(0);
                      face->set_manifold_id(2);
                    }
                  else
                    {
                      // a sector side: before the first tooth or after the last
                      // one; the sides lie at -+ n tau from the sector's middle
                      // (within -+ pi), so the side of the middle tells which
                      const dealii::Tensor<1, 2> m       = face->center() - prm.center;
                      const double               a0      = prm.rotation + 2 * tau * first + (n - 1.) * tau;
                      const double               angle   = std::atan2(m[1], m[0]) - a0;
                      const double               wrapped = angle - 2 * dealii::numbers::PI * std::round(angle / (2 * dealii::numbers::PI));
                      face->set_boundary_id(wrapped < 0 ? 2 : 3);
                    }
                }
              else if (on_circle(a, b))
                face->set_manifold_id(2);
            }
        }
      tria.set_manifold(1, GearOutlineManifold(gear));
      tria.set_manifold(2, dealii::PolarManifold<2>(prm.center));
    }



    using PolygonalMeshGenerators::GearMeshSettings;

    /**
     * The distance of a point from the flank zones of @p settings
     * (GearMeshSettings::zones, or one zone per refined tooth of teeth
     * [@p first, @p first + @p n) with the settings' radii, both flanks),
     * for refine_toward(); with @p fillets, the distance from the root
     * fillets below those flanks instead (their whole length).
     */
    std::function<double(const dealii::Point<2> &)>
    flank_zone_distance(const std::shared_ptr<const SpurGear> &gear,
                        const GearMeshSettings                &settings,
                        const unsigned int                     first,
                        const unsigned int                     n,
                        const bool                             fillets)
    {
      const auto        &prm   = gear->parameters();
      const double       tau   = gear->angular_pitch() / 2;
      const double       scale = gear->tip_radius();
      const unsigned int z     = gear->n_teeth();
      // the zones: given, or one per refined tooth with the common radii and both flanks
      std::vector<GearMeshSettings::FlankZone> zones = settings.zones;
      if (zones.empty())
        {
          const unsigned int first_refined = settings.n_refined_teeth == 0 ? first : settings.first_refined_tooth;
          const unsigned int n_refined     = settings.n_refined_teeth == 0 ? n : settings.n_refined_teeth;
          for (unsigned int k = first_refined; k < first_refined + n_refined; ++k)
            zones.push_back(
              {int(k), settings.refine_from_radius, settings.refine_to_radius, GearMeshSettings::Flank::both});
        }
      // per zone: points of the upper (counter-clockwise) flank of tooth
      // 0 in the tooth's frame between the zone's radii
      const auto                                    &starts = gear->piece_starts();
      std::vector<std::vector<dealii::Tensor<1, 2>>> flank(zones.size());
      for (unsigned int zi = 0; zi < zones.size(); ++zi)
        {
          // (an internal gear's tip lies inside its form radius)
          const double lo   = std::min(gear->form_radius(), gear->tip_radius()),
                       hi   = std::max(gear->form_radius(), gear->tip_radius());
          const double from = zones[zi].from_radius > 0 ? zones[zi].from_radius : lo;
          const double to   = zones[zi].to_radius > 0 ? zones[zi].to_radius : hi;
          AssertThrow(from < to, dealii::ExcMessage("spur_gear(): the refined zone's radii must increase, not " +
                                                    number_string(from) + " to " + number_string(to) + "."));
          const double c = std::cos(-prm.rotation), sn = std::sin(-prm.rotation);
          // the flank (pieces from starts[4]) or the fillet below it (from starts[5])
          const unsigned int piece = fillets ? 5 : 4;
          for (unsigned int i = 0; i <= 800; ++i)
            {
              const dealii::Tensor<1, 2> p =
                gear->outline_point(starts[piece] + (starts[piece + 1] - starts[piece]) * i / 800.) - prm.center;
              const double rad = p.norm();
              if (fillets || (rad >= from - 1e-12 * scale && rad <= to + 1e-12 * scale))
                flank[zi].push_back(dealii::Tensor<1, 2>({c * p[0] - sn * p[1], sn * p[0] + c * p[1]}));
            }
          AssertThrow(!flank[zi].empty(),
                      dealii::ExcMessage("spur_gear(): the refined zone from radius " + number_string(from) + " to " +
                                         number_string(to) + " holds no point of the flank (form radius " +
                                         number_string(gear->form_radius()) + ", tip radius " +
                                         number_string(gear->tip_radius()) + ")."));
        }
      return [=](const dealii::Point<2> &x) {
        const dealii::Tensor<1, 2> rel  = x - prm.center;
        const double               phi  = std::atan2(rel[1], rel[0]) - prm.rotation;
        const int                  k    = std::lround(phi / (2 * tau));
        double                     dmin = std::numeric_limits<double>::max();
        for (unsigned int zi = 0; zi < zones.size(); ++zi)
          {
            // the zone's tooth, if it is k - 1, k or k + 1 (modulo z)
            const int d = ((zones[zi].tooth - k) % int(z) + int(z) + 1) % int(z) - 1;
            if (d < -1 || d > 1)
              continue;
            // x in the frame of that tooth
            const double         a = -2 * tau * (k + d) - prm.rotation;
            dealii::Tensor<1, 2> loc(
              {std::cos(a) * rel[0] - std::sin(a) * rel[1], std::sin(a) * rel[0] + std::cos(a) * rel[1]});
            const auto side = zones[zi].flank;
            for (const bool mirrored : {false, true})
              {
                // the counter-clockwise flank is the upper one, the clockwise its mirror image
                if ((mirrored && side == GearMeshSettings::Flank::counter_clockwise) ||
                    (!mirrored && side == GearMeshSettings::Flank::clockwise))
                  continue;
                const dealii::Tensor<1, 2> q({loc[0], mirrored ? -loc[1] : loc[1]});
                for (const auto &p : flank[zi])
                  dmin = std::min(dmin, (q - p).norm());
              }
          }
        return dmin;
      };
    }
  } // namespace


  namespace PolygonalMeshGenerators
  {
    void
    spur_gear(dealii::Triangulation<2, 2> &tria, const SpurGear &gear_in, const GearMeshSettings &settings)
    {
      const auto         gear  = std::make_shared<const SpurGear>(gear_in);
      const unsigned int z     = gear->n_teeth();
      const bool         whole = settings.n_teeth == 0 || settings.n_teeth >= z;
      const unsigned int first = whole ? 0 : settings.first_tooth % z, n = whole ? z : settings.n_teeth;
      AssertThrow(settings.flank_cell_size >= 0 && std::isfinite(settings.flank_cell_size),
                  dealii::ExcMessage("spur_gear(): the flank cell size must not be negative."));
      BlockMesh                 blocks = tooth_blocks(*gear, first, n);
      dealii::SubCellData       subcell_data;
      std::vector<unsigned int> considered;
      dealii::GridTools::delete_duplicated_vertices(blocks.points, blocks.cells, subcell_data, considered,
                                                    1e-9 * gear->tip_radius());
      tria.clear();
      tria.create_triangulation(blocks.points, blocks.cells, subcell_data);
      set_gear_ids(tria, gear, first, n);
      tria.refine_global(settings.n_global_refinements);
      AssertThrow(settings.fillet_cell_size >= 0 && std::isfinite(settings.fillet_cell_size),
                  dealii::ExcMessage("spur_gear(): the fillet cell size must not be negative."));
      if (settings.flank_cell_size > 0)
        refine_toward(tria, flank_zone_distance(gear, settings, first, n, false), settings.flank_cell_size,
                      settings.layers);
      if (settings.fillet_cell_size > 0)
        refine_toward(tria, flank_zone_distance(gear, settings, first, n, true), settings.fillet_cell_size,
                      settings.layers);
    }


    template <int dim>
    void
    spur_gear(PolygonalMesh<dim> &mesh, const SpurGear &gear, const GearMeshSettings &settings)
    {
      dealii::Triangulation<2, 2> tria;
      spur_gear(tria, gear, settings);
      from_triangulation(mesh, tria);
    }

    template void
    spur_gear(PolygonalMesh<2> &, const SpurGear &, const GearMeshSettings &);
  } // namespace PolygonalMeshGenerators
} // namespace dealvem
