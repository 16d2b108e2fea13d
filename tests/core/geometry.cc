// FVGeometry on randomly distorted and on affine meshes, 2D and 3D (serial and mpirun=2).
//
// Asserts, for meshes from fvfsi::make_mesh:
//  - sum over owned cells of V_P (MPI sum) is the domain measure, and sum of V_P r_P is the domain's
//    first moment (integral of x): the cells' triangle-decomposed polyhedra tile the domain and
//    their volumes and centroids are exact for those polyhedra, whatever the distortion;
//  - every owned cell is closed (its outward face area vectors sum to zero);
//  - sum over the faces of a cell of r_f (x) S_f (S_f out of the cell) is V_P I. This holds only
//    when every face is planar and r_f is its true centroid: on the distorted 2D meshes (faces are
//    segments) and on affine images of a refined cube (2D and 3D; a distorted 3D mesh has warped
//    faces, where it holds only approximately and is not checked). On the affine meshes the cell
//    centroids, volumes, face centres and areas are also compared with the exact values
//    (parallelogram / parallelepiped: centroid = vertex average = deal.II's cell->center());
//  - structure: owned cells have 2 dim faces; every face's kind matches its P and N; its vertices
//    are those of the deal.II face; S_f = area n_f with |n_f| = 1; d_fn > 0 on every face; in 2D
//    r_f is the segment midpoint and n_f is normal to the segment;
//  - ghost cells' centroids and volumes, computed on this rank, are bitwise their owner's;
//  - the boundary-face exchange gives every ghost_boundary face its owner's values (a face's
//    identity and its r_f), and leaves none out;
//  - FVGeometry::reinit() after moving the vertices of the distorted box by x -> A x + t (the
//    triangulation untouched, as in a moving-mesh run) gives V_P -> det A V_P and r_P -> A r_P + t
//    (the decomposition about vertex averages is affine-covariant) and passes all checks above;
//  - face counting: faces with counted_here, summed over the ranks, number the distinct faces of
//    the mesh, (n_cells * 2 dim + n_boundary_faces) / 2, and every processor face is counted on
//    exactly one of its two ranks.
//
// Tolerances: the identities are exact in exact arithmetic; in double precision they hold to
// round-off of per-cell sums of a few terms or global sums of O(10^3) terms. The measured errors
// are <= 2e-14 (FVFSI_TEST_VERBOSE=1 prints them), relative to the natural scale (the domain
// measure, measure x largest coordinate, sum_f |S_f|, V_P, the face area or diameter). Checks use
// 1e-12 on the same scale: a margin of >= 50 over round-off, yet ten orders below any
// discretisation-size error (O(h) ~ 0.1). Global sums are reduced over ranks in an unspecified
// order, so only the verdicts are printed.

#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>

#include <fvfsi/mesh/fv_geometry.h>

#include "fv_core_test_tools.h"

#include <algorithm>
#include <cmath>

using namespace dealii;
using namespace fvfsi_core_test;

/// `planar`: every face is planar and its exact centroid is known (check r_f (x) S_f = V I).
template <int dim>
void check_geometry(std::ostream& out, const parallel::distributed::Triangulation<dim>& tria,
                    const fvfsi::FVGeometry<dim>& fv, const double measure,
                    const Tensor<1, dim>& first_moment, const double length, const bool planar)
{
  const unsigned int n_owned = fv.n_owned_cells();
  out << "cells: " << fv.n_global_cells() << std::endl;

  // Global sums.
  double volume = 0;
  Tensor<1, dim> moment;
  for (unsigned int c = 0; c < n_owned; ++c)
  {
    volume += fv.cell_volume[c];
    moment += fv.cell_volume[c] * fv.centroid[c];
  }
  volume = Utilities::MPI::sum(volume, MPI_COMM_WORLD);
  moment = Utilities::MPI::sum(moment, MPI_COMM_WORLD);
  out << format("domain measure: %.8f", measure) << std::endl;
  check(out, "sum of V_P equals the domain measure", std::abs(volume - measure) / measure, 1e-12);
  check(out, "sum of V_P r_P equals the first moment of the domain",
        (moment - first_moment).norm() / (measure * length), 1e-12);

  // Per owned cell: closedness, the second-moment identity, number of faces, P/N relation.
  double closed_error = 0, second_moment_error = 0;
  bool faces_per_cell_ok = true, cell_face_links_ok = true, positive_volumes = true;
  for (unsigned int c = 0; c < n_owned; ++c)
  {
    positive_volumes = positive_volumes && fv.cell_volume[c] > 0;
    faces_per_cell_ok = faces_per_cell_ok && fv.cell_faces(c).size() == 2 * dim;
    Tensor<1, dim> sum_S;
    double sum_area = 0;
    Tensor<2, dim> sum_rS;
    for (const unsigned int f : fv.cell_faces(c))
    {
      const auto& face = fv.faces[f];
      cell_face_links_ok = cell_face_links_ok && (face.P == c || face.N == c);
      const Tensor<1, dim> S = face.P == c ? face.S : -face.S;
      sum_S += S;
      sum_area += face.area;
      sum_rS += outer_product(face.centre, S);
    }
    closed_error = std::max(closed_error, sum_S.norm() / sum_area);
    if (planar)
      second_moment_error = std::max(
        second_moment_error,
        (sum_rS - fv.cell_volume[c] * unit_symmetric_tensor<dim>()).norm() / fv.cell_volume[c]);
  }
  check(out, "owned cells have positive volume", positive_volumes);
  check(out, "owned cells have 2 dim faces, each with P or N = the cell",
        faces_per_cell_ok && cell_face_links_ok);
  check(out, "every owned cell is closed: sum_f S_f = 0", closed_error, 1e-12);
  if (planar)
    check(out, "sum_f r_f (x) S_f = V_P I on every owned cell", second_moment_error, 1e-12);

  // Ghost cells: their geometry, computed on this rank, has the same bits as their owner's (a
  // parallel run must not depend on who computes what).
  {
    std::array<fvfsi::CellVector, dim + 1> data;
    for (auto& v : data)
      v = fv.make_cell_vector();
    for (unsigned int c = 0; c < n_owned; ++c)
    {
      for (unsigned int d = 0; d < dim; ++d)
        data[d].local_element(c) = fv.centroid[c][d];
      data[dim].local_element(c) = fv.cell_volume[c];
    }
    bool same = true;
    for (auto& v : data)
      v.update_ghost_values();
    for (unsigned int c = n_owned; c < fv.n_relevant_cells(); ++c)
    {
      for (unsigned int d = 0; d < dim; ++d)
        same = same && data[d].local_element(c) == fv.centroid[c][d];
      same = same && data[dim].local_element(c) == fv.cell_volume[c];
    }
    check(out, "ghost cells' r_P and V_P are bitwise their owner's", same);
  }

  // Ghost cells list only their boundary faces.
  bool ghost_faces_ok = true;
  for (unsigned int c = n_owned; c < fv.n_relevant_cells(); ++c)
    for (const unsigned int f : fv.cell_faces(c))
      ghost_faces_ok =
        ghost_faces_ok && fv.faces[f].P == c && fv.faces[f].kind == fvfsi::FaceKind::ghost_boundary;
  check(out, "ghost cells list only their ghost_boundary faces", ghost_faces_ok);

  // The boundary-face exchange: every ghost_boundary face receives what the owner of its cell
  // stored on the same face - here the face's identity (global cell index, face number) as a
  // scalar and, as a tensor of dim doubles, the owner's r_f, which is bitwise this rank's own.
  {
    std::vector<double> id(fv.faces.size(), -1);
    std::vector<Tensor<1, dim>> centre(fv.faces.size());
    for (const unsigned int f : fv.boundary_faces())
    {
      id[f] = fv.global_index(fv.faces[f].P) * 2 * dim + fv.faces[f].face_no;
      centre[f] = fv.faces[f].centre;
    }
    fv.boundary_face_exchange().update(id);
    fv.boundary_face_exchange().update(centre);
    bool received = true;
    for (const unsigned int f : fv.all_boundary_faces())
      received = received &&
                 id[f] == double(fv.global_index(fv.faces[f].P) * 2 * dim + fv.faces[f].face_no) &&
                 centre[f] == fv.faces[f].centre;
    check(out, "ghost_boundary faces receive their owner's face values (boundary face exchange)",
          received);
  }

  // Per face.
  bool kinds_ok = true, vertices_ok = true, neighbours_ok = true, patches_ok = true;
  double min_dn = std::numeric_limits<double>::max(), normal_error = 0, S_error = 0;
  double midpoint_error = 0, tangency_error = 0;
  unsigned int n_counted = 0, n_boundary_kind = 0, n_processor = 0, n_processor_counted = 0;
  for (const auto& face : fv.faces)
  {
    using fvfsi::FaceKind;
    using fvfsi::invalid_cell;
    const bool P_owned = face.P < n_owned;
    switch (face.kind)
    {
      case FaceKind::interior:
        kinds_ok = kinds_ok && P_owned && face.N < n_owned && face.counted_here;
        break;
      case FaceKind::processor:
        kinds_ok = kinds_ok && P_owned && face.N >= n_owned && face.N < fv.n_relevant_cells();
        ++n_processor;
        n_processor_counted += face.counted_here ? 1 : 0;
        break;
      case FaceKind::boundary:
        kinds_ok = kinds_ok && P_owned && face.N == invalid_cell && face.counted_here;
        ++n_boundary_kind;
        break;
      case FaceKind::ghost_boundary:
        kinds_ok = kinds_ok && !P_owned && face.N == invalid_cell && !face.counted_here;
        break;
    }
    n_counted += face.counted_here ? 1 : 0;

    const auto cell = fv.cell(face.P);
    const auto dealii_face = cell->face(face.face_no);
    std::vector<unsigned int> a(face.vertices.begin(), face.vertices.end()), b;
    for (const unsigned int v : dealii_face->vertex_indices())
      b.push_back(dealii_face->vertex_index(v));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    vertices_ok = vertices_ok && a == b;
    if (face.N == invalid_cell)
      patches_ok =
        patches_ok && cell->at_boundary(face.face_no) && face.patch == dealii_face->boundary_id();
    else
      neighbours_ok = neighbours_ok && !cell->at_boundary(face.face_no) &&
                      cell->neighbor(face.face_no)->id() == fv.cell(face.N)->id();

    min_dn = std::min(min_dn, face.d_n / face.d.norm());
    normal_error = std::max(normal_error, std::abs(face.n.norm() - 1));
    S_error = std::max(S_error, (face.S - face.area * face.n).norm() / face.area);
    if (dim == 2)
    {
      const Point<dim> x0 = fv.vertices()[face.vertices[0]], x1 = fv.vertices()[face.vertices[1]];
      midpoint_error = std::max(midpoint_error, (face.centre - (x0 + x1) / 2).norm() / face.area);
      tangency_error = std::max(tangency_error, std::abs(face.n * (x1 - x0)) / face.area);
    }
  }
  check(out, "face kinds match their P and N", kinds_ok);
  check(out, "face vertices are those of the deal.II face", vertices_ok);
  check(out, "N is the deal.II neighbour across face_no", neighbours_ok);
  check(out, "boundary faces are at the boundary, patch = boundary id", patches_ok);
  check(out, "d_fn > 0 on every face", min_dn > 0);
  check(out, "|n_f| = 1", normal_error, 1e-12);
  check(out, "S_f = area n_f", S_error, 1e-12);
  if (dim == 2)
  {
    check(out, "2D: r_f is the segment midpoint", midpoint_error, 1e-12);
    check(out, "2D: n_f is normal to the segment", tangency_error, 1e-12);
  }

  // Face counting.
  unsigned int n_boundary_faces = 0;
  for (const auto& cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const unsigned int f : cell->face_indices())
        n_boundary_faces += cell->at_boundary(f) ? 1 : 0;
  n_boundary_faces = Utilities::MPI::sum(n_boundary_faces, MPI_COMM_WORLD);
  const unsigned long long expected =
    (fv.n_global_cells() * GeometryInfo<dim>::faces_per_cell + n_boundary_faces) / 2;
  const unsigned long long counted =
    Utilities::MPI::sum<unsigned long long>(n_counted, MPI_COMM_WORLD);
  out << "distinct faces: " << expected << ", boundary faces: " << n_boundary_faces << std::endl;
  check(out, "faces counted_here (summed over ranks) = distinct faces", counted == expected);
  check(out, "boundary-kind faces (summed over ranks) = boundary faces",
        Utilities::MPI::sum(n_boundary_kind, MPI_COMM_WORLD) == n_boundary_faces);
  if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    check(out, "parallel: there are processor faces (the checks above are not vacuous)",
          Utilities::MPI::sum(n_processor, MPI_COMM_WORLD) > 0);
  check(out, "every processor face is counted on exactly one of its two ranks",
        2 * Utilities::MPI::sum(n_processor_counted, MPI_COMM_WORLD) ==
          Utilities::MPI::sum(n_processor, MPI_COMM_WORLD));
}

/// Exact values on an affine image of a refined cube (planar faces): cell volume and centroid,
/// face centre and area.
template <int dim>
void check_affine_exact(std::ostream& out, const fvfsi::FVGeometry<dim>& fv,
                        const double cell_volume)
{
  double volume_error = 0, centroid_error = 0, centre_error = 0, area_error = 0,
         orthogonality_error = 0;
  for (unsigned int c = 0; c < fv.n_relevant_cells(); ++c)
  {
    const auto cell = fv.cell(c);
    volume_error = std::max(volume_error, std::abs(fv.cell_volume[c] - cell_volume) / cell_volume);
    centroid_error =
      std::max(centroid_error, (fv.centroid[c] - cell->center()).norm() / cell->diameter());
  }
  for (const auto& face : fv.faces)
  {
    const auto dealii_face = fv.cell(face.P)->face(face.face_no);
    const double h = dealii_face->diameter();
    centre_error = std::max(centre_error, (face.centre - dealii_face->center()).norm() / h);
    area_error = std::max(area_error, std::abs(face.area - dealii_face->measure()) / face.area);
    // n_f is normal to every edge of the face.
    for (unsigned int i = 0; i < face.vertices.size(); ++i)
    {
      const Tensor<1, dim> edge = fv.vertices()[face.vertices[(i + 1) % face.vertices.size()]] -
                                  fv.vertices()[face.vertices[i]];
      orthogonality_error = std::max(orthogonality_error, std::abs(face.n * edge) / edge.norm());
    }
  }
  check(out, "affine: V_P is |det A| h^dim (owned and ghost cells)", volume_error, 1e-12);
  check(out, "affine: r_P is the exact centroid (owned and ghost cells)", centroid_error, 1e-12);
  check(out, "affine: r_f is the exact face centroid", centre_error, 1e-12);
  check(out, "affine: area is the exact face area", area_error, 1e-12);
  check(out, "affine: n_f is normal to the face's edges", orthogonality_error, 1e-12);
}

template <int dim>
void test_distorted_box(std::ostream& out)
{
  out << "--- " << dim << "D subdivided_hyper_rectangle, distortion 0.25 of the refined mesh"
      << std::endl;
  parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
  // (-1, 0.5[, 0]) .. (2, 2[, 1.5]) in 2 x 1 [x 1] coarse cells.
  const std::string arguments =
    dim == 2 ? "2, 1 : -1, 0.5 : 2, 2 : true" : "2, 1, 1 : -1, 0.5, 0 : 2, 2, 1.5 : true";
  make_test_mesh(tria, "subdivided_hyper_rectangle", arguments, dim == 2 ? 4 : 3, 0.25);
  const fvfsi::FVGeometry<dim> fv(tria);
  const double measure = dim == 2 ? 3 * 1.5 : 3 * 1.5 * 1.5;
  Tensor<1, dim> centre;
  centre[0] = 0.5;
  centre[1] = 1.25;
  if (dim == 3)
    centre[dim - 1] = 0.75;
  check_geometry(out, tria, fv, measure, measure * centre, 2.0, dim == 2);

  // FVGeometry::reinit() with the vertices moved by x -> A x + t (a mesh motion that keeps the
  // triangulation): the triangle decomposition about vertex averages is affine-covariant, so
  // V_P -> det A V_P and r_P -> A r_P + t exactly (owned and ghost cells).
  Tensor<2, dim> A;
  Tensor<1, dim> t;
  const double A3[3][3] = {{0.9, 0.2, 0.1}, {-0.3, 1.1, 0.05}, {0.15, -0.1, 1.2}};
  for (unsigned int i = 0; i < dim; ++i)
  {
    t[i] = 0.1 * (i + 1);
    for (unsigned int j = 0; j < dim; ++j)
      A[i][j] = A3[i][j];
  }
  out << "--- the same mesh, FVGeometry::reinit() with the vertices moved by x -> A x + t"
      << std::endl;
  fvfsi::FVGeometry<dim> moved(tria);
  std::vector<Point<dim>> x = fv.vertices();
  for (auto& p : x)
    p = Point<dim>(A * p + t);
  moved.reinit(x);
  double volume_error = 0, centroid_error = 0;
  for (unsigned int c = 0; c < fv.n_relevant_cells(); ++c)
  {
    volume_error =
      std::max(volume_error, std::abs(moved.cell_volume[c] - determinant(A) * fv.cell_volume[c]) /
                               moved.cell_volume[c]);
    centroid_error =
      std::max(centroid_error, (moved.centroid[c] - (A * fv.centroid[c] + t)).norm() /
                                 std::pow(fv.cell_volume[c], 1.0 / dim));
  }
  check(out, "reinit(A x + t): V_P -> det A V_P", volume_error, 1e-12);
  check(out, "reinit(A x + t): r_P -> A r_P + t", centroid_error, 1e-12);
  check_geometry(out, tria, moved, determinant(A) * measure,
                 determinant(A) * measure * (A * centre + t), 3.0, dim == 2);
}

template <int dim>
void test_hyper_L(std::ostream& out)
{
  out << "--- " << dim << "D hyper_L (-1, 1), distortion 0.25 of the refined mesh" << std::endl;
  const unsigned int refinements = dim == 2 ? 4 : 2;
  parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD), reference(MPI_COMM_WORLD);
  make_test_mesh(tria, "hyper_L", "-1 : 1 : false", refinements, 0.25);
  // The undistorted mesh (same boundary, same domain) gives the exact first moment: its cells
  // are squares / cubes, whose centroid is deal.II's center().
  make_test_mesh(reference, "hyper_L", "-1 : 1 : false", refinements, 0.0);
  Tensor<1, dim> first_moment;
  for (const auto& cell : reference.active_cell_iterators())
    if (cell->is_locally_owned())
      first_moment += cell->measure() * cell->center();
  first_moment = Utilities::MPI::sum(first_moment, MPI_COMM_WORLD);
  const fvfsi::FVGeometry<dim> fv(tria);
  const double measure = std::pow(2.0, dim) - 1; // the cube (-1, 1)^dim minus one quadrant/octant
  check_geometry(out, tria, fv, measure, first_moment, 1.0, dim == 2);
}

template <int dim>
void test_affine(std::ostream& out)
{
  out << "--- " << dim << "D hyper_cube (0, 1) refined, mapped by x -> A x + t" << std::endl;
  const unsigned int refinements = dim == 2 ? 4 : 3;
  parallel::distributed::Triangulation<dim> tria(MPI_COMM_WORLD);
  make_test_mesh(tria, "hyper_cube", "0 : 1 : true", refinements, 0.0);
  Tensor<2, dim> A;
  Tensor<1, dim> t;
  const double A3[3][3] = {{1.2, 0.3, -0.2}, {0.1, 0.9, 0.25}, {-0.15, 0.2, 1.1}};
  const double t3[3] = {0.5, -0.3, 0.2};
  for (unsigned int i = 0; i < dim; ++i)
  {
    t[i] = t3[i];
    for (unsigned int j = 0; j < dim; ++j)
      A[i][j] = A3[i][j];
  }
  GridTools::transform([&](const Point<dim>& x) { return Point<dim>(A * x + t); }, tria);
  const fvfsi::FVGeometry<dim> fv(tria);
  const double det = determinant(A);
  Point<dim> centre;
  for (unsigned int d = 0; d < dim; ++d)
    centre[d] = 0.5;
  const Tensor<1, dim> first_moment = det * (A * centre + t);
  out << format("det A = %.6f", det) << std::endl;
  check_geometry(out, tria, fv, det, first_moment, 2.0, true);
  check_affine_exact(out, fv, det * std::pow(0.5, dim * refinements));
}

int main(int argc, char** argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream out = open_output();
  test_distorted_box<2>(out);
  test_hyper_L<2>(out);
  test_affine<2>(out);
  test_distorted_box<3>(out);
  test_hyper_L<3>(out);
  test_affine<3>(out);
}
