// ---------------------------------------------------------------------
// This file is part of dealvem.
// SPDX-License-Identifier: LGPL-2.1-or-later
// ---------------------------------------------------------------------
// A block mesh of a gear rack: per half tooth, blocks between the tooth
// axis and the flank, a fillet block, two root blocks under the fillet and
// the space, and a body of two columns in layers down to the back line. The
// faces on the teeth carry a chart manifold whose chart is the rack's
// outline coordinate; everything else is flat.
#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/tria.h>

#include <dealvem/base/number_string.h>
#include <dealvem/mesh/gear_rack.h>
#include <dealvem/mesh/generators.h>

#include <cmath>
#include <functional>
#include <memory>

namespace dealvem
{
  using internal::number_string;

  namespace
  {
    using Quad = std::array<dealii::Point<2>, 4>;

    /// The rack's outline as a deal.II chart manifold (not periodic: the
    /// rack ends at its sides).
    class RackOutlineManifold : public dealii::ChartManifold<2, 2, 1>
    {
    public:
      explicit RackOutlineManifold(const std::shared_ptr<const GearRack> &rack)
        : rack(rack)
      {}

      std::unique_ptr<dealii::Manifold<2, 2>>
      clone() const override
      {
        return std::make_unique<RackOutlineManifold>(rack);
      }

      dealii::Point<1>
      pull_back(const dealii::Point<2> &space_point) const override
      {
        return dealii::Point<1>(rack->outline_coordinate(space_point));
      }

      dealii::Point<2>
      push_forward(const dealii::Point<1> &chart_point) const override
      {
        return rack->outline_point(chart_point[0]);
      }

      dealii::DerivativeForm<1, 1, 2>
      push_forward_gradient(const dealii::Point<1> &chart_point) const override
      {
        const dealii::Tensor<1, 2>      t = rack->outline_tangent(chart_point[0]);
        dealii::DerivativeForm<1, 1, 2> grad;
        grad[0][0] = t[0];
        grad[1][0] = t[1];
        return grad;
      }

    private:
      std::shared_ptr<const GearRack> rack;
    };


    /**
     * The blocks of the right half of tooth 0 in the tooth's frame (its axis
     * at x = 0, the pitch line at y = 0), counter-clockwise corners; the
     * left half is their mirror image.
     */
    std::vector<Quad>
    half_tooth_blocks(const GearRack &rack)
    {
      const auto  &prm = rack.parameters();
      const auto  &st  = rack.piece_starts();
      const double p = rack.pitch(), x0 = rack.tooth_axis(0);
      const auto   local = [&](const double s) {
        const dealii::Point<2> q = rack.outline_point(s);
        return dealii::Point<2>(q[0] - x0, q[1] - prm.pitch_line_height);
      };
      // the right flank runs from the tip corner (st[4]) down to the form point (st[5])
      const double       half_width = 0.5 * rack.tooth_thickness(prm.pitch_line_height);
      const unsigned int n_flank    = std::max(1, static_cast<int>(std::lround((st[5] - st[4]) / (1.2 * half_width))));
      std::vector<dealii::Point<2>> flank(n_flank + 1), axis(n_flank + 1);
      for (unsigned int i = 0; i <= n_flank; ++i)
        {
          flank[i] = local(st[4] + (st[5] - st[4]) * i / n_flank);
          axis[i]  = dealii::Point<2>(0., flank[i][1]);
        }
      // without a fillet (sharp root corners) the fillet block is left out:
      // its middle point is the corner
      const bool             has_fillet = st[6] - st[5] > 1e-12 * p;
      const dealii::Point<2> form = flank[n_flank], fillet_mid = local(has_fillet ? 0.5 * (st[5] + st[6]) : st[5]);
      const dealii::Point<2> space(p / 2, rack.root_height() - prm.pitch_line_height);
      // the root blocks reach down to y_m: about the space's half width below the root line
      const double w   = p / 2 - fillet_mid[0];
      const double y_m = std::min(space[1] - w, fillet_mid[1] - 0.5 * w);
      const double y_b = rack.bottom_height() - prm.pitch_line_height;
      AssertThrow(y_m - y_b > 0.05 * (space[1] - y_b),
                  dealii::ExcMessage("gear_rack(): the body depth " + number_string(prm.body_depth) +
                                     " leaves no body under the teeth (the root blocks reach " +
                                     number_string(space[1] - y_m) + " below the root line); choose a deeper body."));
      const dealii::Point<2> fillet_axis(0., fillet_mid[1]), body_axis(0., y_m), body_mid(fillet_mid[0], y_m),
        body_space(p / 2, y_m);

      std::vector<Quad> blocks;
      for (unsigned int i = 0; i < n_flank; ++i)
        blocks.push_back({{axis[i + 1], flank[i + 1], flank[i], axis[i]}});
      if (has_fillet)
        blocks.push_back({{fillet_axis, fillet_mid, form, axis[n_flank]}});
      blocks.push_back({{body_axis, body_mid, fillet_mid, fillet_axis}});
      blocks.push_back({{body_mid, body_space, space, fillet_mid}});
      // the body: layers about 0.75 of the half pitch thick, down to the back line
      const unsigned int n_layers = std::max(1, static_cast<int>(std::ceil((y_m - y_b) / (0.75 * p / 2))));
      for (unsigned int l = 0; l < n_layers; ++l)
        {
          const double top = y_m - (y_m - y_b) * l / n_layers;
          const double bot = (l + 1 == n_layers ? y_b : y_m - (y_m - y_b) * (l + 1) / n_layers);
          blocks.push_back({{dealii::Point<2>(0., bot), dealii::Point<2>(fillet_mid[0], bot),
                             dealii::Point<2>(fillet_mid[0], top), dealii::Point<2>(0., top)}});
          blocks.push_back({{dealii::Point<2>(fillet_mid[0], bot), dealii::Point<2>(p / 2, bot),
                             dealii::Point<2>(p / 2, top), dealii::Point<2>(fillet_mid[0], top)}});
        }
      return blocks;
    }


    /// The coarse triangulation of the whole rack: the half-tooth blocks
    /// placed at every tooth, mirrored for the left halves.
    void
    coarse_rack(dealii::Triangulation<2, 2> &tria, const GearRack &rack)
    {
      const auto                       half = half_tooth_blocks(rack);
      std::vector<dealii::Point<2>>    points;
      std::vector<dealii::CellData<2>> cells;
      const auto                       add_quad = [&](const Quad &ccw) {
        dealii::CellData<2> cell;
        // deal.II numbers a quadrilateral's vertices lexicographically
        const unsigned int order[4] = {0, 1, 3, 2};
        for (unsigned int v = 0; v < 4; ++v)
          {
            points.push_back(ccw[order[v]]);
            cell.vertices[v] = points.size() - 1;
          }
        cell.material_id = 0;
        cells.push_back(cell);
      };
      for (unsigned int k = 0; k < rack.n_teeth(); ++k)
        {
          const auto place = [&](const dealii::Point<2> &q, const bool mirror) {
            return dealii::Point<2>(rack.tooth_axis(k) + (mirror ? -q[0] : q[0]),
                                    rack.parameters().pitch_line_height + q[1]);
          };
          for (const auto &b : half)
            {
              add_quad({{place(b[0], false), place(b[1], false), place(b[2], false), place(b[3], false)}});
              // the mirror image reverses the orientation
              add_quad({{place(b[1], true), place(b[0], true), place(b[3], true), place(b[2], true)}});
            }
        }
      dealii::SubCellData       subcell_data;
      std::vector<unsigned int> considered;
      dealii::GridTools::delete_duplicated_vertices(points, cells, subcell_data, considered, 1e-9 * rack.pitch());
      tria.clear();
      tria.create_triangulation(points, cells, subcell_data);
    }


    /// Boundary and manifold ids: 1 the teeth (manifold 1, the outline),
    /// 0 the back line, 2 and 3 the left and right sides; all else flat.
    void
    set_rack_ids(dealii::Triangulation<2, 2> &tria, const std::shared_ptr<const GearRack> &rack)
    {
      const double tol = 1e-9 * rack->pitch(), y_b = rack->bottom_height();
      const auto   ext = rack->extent();
      for (const auto &cell : tria.active_cell_iterators())
        {
          cell->set_manifold_id(dealii::numbers::flat_manifold_id);
          for (const auto f : cell->face_indices())
            {
              const auto face = cell->face(f);
              face->set_manifold_id(dealii::numbers::flat_manifold_id);
              if (!face->at_boundary())
                continue;
              const dealii::Point<2> a = face->vertex(0), b = face->vertex(1);
              if (std::abs(a[1] - y_b) < tol && std::abs(b[1] - y_b) < tol)
                face->set_boundary_id(0);
              else if (rack->distance_to_outline(a) < tol && rack->distance_to_outline(b) < tol)
                {
                  face->set_boundary_id(1);
                  face->set_manifold_id(1);
                }
              else
                face->set_boundary_id(face->center()[0] < 0.5 * (ext[0] + ext[1]) ? 2 : 3);
            }
        }
      tria.set_manifold(1, RackOutlineManifold(rack));
    }


    using PolygonalMeshGenerators::RackMeshSettings;

    /// The distance of a point from the segment [a, b].
    double
    segment_distance(const dealii::Point<2> &x, const dealii::Point<2> &a, const dealii::Point<2> &b)
    {
      const dealii::Tensor<1, 2> d = b - a;
      const double               t = std::clamp((x - a) * d / std::max(d * d, 1e-300), 0., 1.);
      return x.distance(a + t * d);
    }


    /**
     * The distance of a point from the flank zones of @p settings (or from
     * both whole flanks of every tooth if there are none), for
     * refine_toward(); with @p fillets, from the root fillets below those
     * flanks instead.
     */
    std::function<double(const dealii::Point<2> &)>
    zone_distance(const std::shared_ptr<const GearRack> &rack, const RackMeshSettings &settings, const bool fillets)
    {
      auto zones = settings.zones;
      if (zones.empty())
        for (unsigned int k = 0; k < rack->n_teeth(); ++k)
          zones.push_back({k});
      const auto  &prm = rack->parameters();
      const double H = prm.pitch_line_height, a = prm.pressure_angle;
      const double rho = prm.root_fillet_radius * prm.module;
      // per zone and side: the flank segment (or the fillet's centre and its
      // arc's angles), sides -1 (left) and +1 (right)
      struct Part
      {
        dealii::Point<2> a, b;
        int              side;
      };
      std::vector<Part> parts;
      for (const auto &z : zones)
        {
          AssertThrow(z.tooth < rack->n_teeth(),
                      dealii::ExcMessage("gear_rack(): a refined zone's tooth " + std::to_string(z.tooth) +
                                         " is not one of the rack's " + std::to_string(rack->n_teeth()) + " teeth."));
          const double from = std::max(H + std::max(z.from_height, -1e300), rack->form_height());
          const double to   = std::min(H + std::min(z.to_height, 1e300), rack->tip_height());
          AssertThrow(from < to,
                      dealii::ExcMessage("gear_rack(): the refined zone of tooth " + std::to_string(z.tooth) +
                                         " holds no point of the flank (heights " + number_string(from - H) + " to " +
                                         number_string(to - H) + " above the pitch line)."));
          const double c = rack->tooth_axis(z.tooth);
          for (const int side : {-1, 1})
            if (z.flank == RackMeshSettings::Flank::both || (side < 0) == (z.flank == RackMeshSettings::Flank::left))
              parts.push_back({dealii::Point<2>(c + side * 0.5 * rack->tooth_thickness(from), from),
                               dealii::Point<2>(c + side * 0.5 * rack->tooth_thickness(to), to), side});
        }
      return [=](const dealii::Point<2> &x) {
        double d = std::numeric_limits<double>::max();
        for (const auto &part : parts)
          if (!fillets)
            d = std::min(d, segment_distance(x, part.a, part.b));
          else
            {
              // the fillet of the tooth of that flank on that side: the arc
              // from straight below its centre to the flank's normal
              const unsigned int     k  = std::lround((0.5 * (part.a[0] + part.b[0]) - prm.position) / rack->pitch());
              const dealii::Point<2> cr = rack->fillet_center(k);
              const dealii::Point<2> centre(rack->tooth_axis(k) + part.side * (cr[0] - rack->tooth_axis(k)), cr[1]);
              const dealii::Point<2> bottom(centre[0], centre[1] - rho),
                end(centre[0] - part.side * rho * std::cos(a), centre[1] - rho * std::sin(a));
              const dealii::Tensor<1, 2> r = x - centre;
              // within the arc's sector: below the centre, on the flank's
              // side, at least alpha below the horizontal
              const double xr = -part.side * r[0], yr = -r[1];
              const bool   inside = xr >= 0 && yr >= 0 && std::atan2(yr, xr) >= a;
              d = std::min(d, inside ? std::abs(r.norm() - rho) : std::min(x.distance(bottom), x.distance(end)));
            }
        return d;
      };
    }
  } // namespace


  namespace PolygonalMeshGenerators
  {
    void
    gear_rack(dealii::Triangulation<2, 2> &tria, const GearRack &rack_in, const RackMeshSettings &settings)
    {
      AssertThrow(settings.flank_cell_size >= 0 && std::isfinite(settings.flank_cell_size),
                  dealii::ExcMessage("gear_rack(): the flank cell size must not be negative."));
      AssertThrow(settings.fillet_cell_size >= 0 && std::isfinite(settings.fillet_cell_size),
                  dealii::ExcMessage("gear_rack(): the fillet cell size must not be negative."));
      AssertThrow(settings.layers > 0 && std::isfinite(settings.layers),
                  dealii::ExcMessage("gear_rack(): the number of layers must be positive."));
      const auto rack = std::make_shared<const GearRack>(rack_in);
      coarse_rack(tria, *rack);
      set_rack_ids(tria, rack);
      tria.refine_global(settings.n_global_refinements);
      if (settings.flank_cell_size > 0)
        refine_toward(tria, zone_distance(rack, settings, false), settings.flank_cell_size, settings.layers);
      if (settings.fillet_cell_size > 0 && rack->parameters().root_fillet_radius > 0)
        refine_toward(tria, zone_distance(rack, settings, true), settings.fillet_cell_size, settings.layers);
    }


    template <int dim>
    void
    gear_rack(PolygonalMesh<dim> &mesh, const GearRack &rack, const RackMeshSettings &settings)
    {
      dealii::Triangulation<2, 2> tria;
      gear_rack(tria, rack, settings);
      from_triangulation(mesh, tria);
    }

    template void
    gear_rack(PolygonalMesh<2> &, const GearRack &, const RackMeshSettings &);
  } // namespace PolygonalMeshGenerators
} // namespace dealvem
