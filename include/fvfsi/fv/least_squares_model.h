#pragma once
// The multi-secant least-squares model behind the interface quasi-Newton coupling (IQN-ILS,
// Degroote et al., the paper's ref [43]) and the solid's Anderson acceleration: one model, two
// users. From the differences between iterations of a residual, dR_k, and of the values that
// produced it, dX_k (the columns, newest first), it returns for a residual r
//
//   correction = sum_k c_k dX_k,   c = argmin | r + sum_k c_k dR_k |_2,
//
// the least-squares inverse Jacobian applied to -r. IQN-ILS adds it to the solid's answer d~,
// Anderson to the fixed-point image G(x); IQN-IMVJ also takes the fitted part sum_k c_k dR_k
// (its inverse Jacobian of earlier time steps acts on the rest of r) and, at the end of a time
// step, the kept columns with the pseudo-inverse of [dR_k] (kept_secants(), for its update).
//
// The least-squares problem is solved by deal.II's ImplicitQR, which needs nothing of the columns
// but their dot products (it keeps R with R^T R = A^T A). They are computed all at once, as the
// Gram matrix of the columns and r: for the solid's distributed vectors one MPI sum per call
// instead of one per product (some 75 at depth 10, each a meeting of all ranks), with the same
// local sums as the vectors' own products, so the results are the same to the last bit. The
// interface's vectors are replicated (no MPI sum). Columns are taken newest first, and one whose
// part orthogonal to the newer ones is at most `filter` times its norm is left out (the QR filter
// of IQN methods: after a few iterations of a converging step old columns become nearly
// dependent on new ones, and kept, they amplify round-off into the update). The coupling's
// filter is `Coupling/QR filter` (default 1e-2), the solid's Anderson acceleration uses 1e-5.

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_block_vector.h>
#include <deal.II/lac/qr.h>
#include <deal.II/lac/vector.h>

#include <boost/serialization/list.hpp>

#include <cmath>
#include <iterator>
#include <list>
#include <stdexcept>
#include <vector>

namespace fvfsi
{
  namespace internal
  {
    /// What the Gram matrix needs of a vector type: this rank's part of a vector as serial
    /// blocks, and the communicator that sums their products.
    template <typename VectorType>
    struct GramTraits;

    /// A replicated vector: the whole vector, no sum.
    template <>
    struct GramTraits<dealii::Vector<double>>
    {
      static std::vector<dealii::Vector<double>> local(const dealii::Vector<double>& v)
      {
        return {v};
      }
      static MPI_Comm comm(const dealii::Vector<double>&) { return MPI_COMM_SELF; }
    };

    /// A distributed block vector: the owned entries of each block. Their serial product is
    /// the local part of the block vector's own operator* (the same arithmetic), which sums the
    /// blocks in order and then over the ranks.
    template <>
    struct GramTraits<dealii::LinearAlgebra::distributed::BlockVector<double>>
    {
      using BlockVector = dealii::LinearAlgebra::distributed::BlockVector<double>;
      static std::vector<dealii::Vector<double>> local(const BlockVector& v)
      {
        std::vector<dealii::Vector<double>> blocks;
        for (unsigned int b = 0; b < v.n_blocks(); ++b)
          blocks.emplace_back(v.block(b).begin(),
                              v.block(b).begin() + v.block(b).locally_owned_size());
        return blocks;
      }
      static MPI_Comm comm(const BlockVector& v) { return v.block(0).get_mpi_communicator(); }
    };

    /// A column as ImplicitQR sees it: entry k of a Gram matrix G (G_ij = v_i . v_j).
    struct GramColumn
    {
      using value_type = double;
      const dealii::FullMatrix<double>* G;
      unsigned int k;
      double operator*(const GramColumn& other) const { return (*G)(k, other.k); }
      double norm_sqr() const { return (*G)(k, k); }
      double l2_norm() const { return std::sqrt(norm_sqr()); }
      // ImplicitQR's products with A itself (multiply_with_A, ..._Q) need the entries, which a
      // Gram column does not have; they are compiled but never called here.
      GramColumn& operator=(double) { throw std::logic_error("GramColumn has no entries"); }
      void add(double, const GramColumn&) { throw std::logic_error("GramColumn has no entries"); }
    };
  } // namespace internal

  template <typename VectorType>
  class LeastSquaresModel
  {
  public:
    /// `filter` as above (0: keep every column that is not exactly dependent).
    explicit LeastSquaresModel(const double filter = 0) : filter(filter) {}
    void set_filter(const double f) { filter = f; }

    /// Add the newest pair of columns; `tag` marks them (e.g. with their time step). The
    /// storage of a forgotten column is reused: a distributed vector made anew takes a meeting of
    /// the ranks (its copy agrees on the layout with an MPI min), a reused one is filled in place.
    void add_column(const VectorType& dR, const VectorType& dX, const unsigned int tag = 0)
    {
      if (spare.empty())
        columns.push_front(Columns{dR, dX, tag});
      else
      {
        columns.splice(columns.begin(), spare, spare.begin());
        columns.front().dR = dR;
        columns.front().dX = dX;
        columns.front().tag = tag;
      }
    }
    /// Forget the oldest column pair.
    void drop_oldest() { spare.splice(spare.begin(), columns, std::prev(columns.end())); }
    /// Forget the columns tagged below `tag`.
    void drop_tagged_before(const unsigned int tag)
    {
      while (!columns.empty() && columns.back().tag < tag)
        drop_oldest();
    }
    void clear() { spare.splice(spare.begin(), columns); }
    unsigned int size() const { return columns.size(); }
    /// The tag of the oldest column (size() > 0).
    unsigned int oldest_tag() const { return columns.back().tag; }
    /// Columns the filter kept in the last call of correction().
    unsigned int n_used() const { return used; }

    /// `result` (sized like r) = sum_k c_k dX_k with c = argmin |r + sum_k c_k dR_k|; false
    /// (result untouched) if no column is usable. With `fitted`, also fitted = sum_k c_k dR_k
    /// (r + fitted is the part of r the columns do not explain; IQN-IMVJ applies its inverse
    /// Jacobian of earlier time steps to it).
    bool correction(const VectorType& r, VectorType& result, VectorType* fitted = nullptr) const
    {
      const dealii::FullMatrix<double> G = gram(&r);
      dealii::ImplicitQR<internal::GramColumn> qr;
      const std::vector<const Columns*> kept = factorize(qr, G);
      if (kept.empty())
        return false;
      // c = -R^-1 Q^T r with Q^T r = R^-T A^T r (A = [dR_k], R its QR factor).
      dealii::Vector<double> ATr(used), QTr(used), c(used);
      qr.multiply_with_AT(ATr, internal::GramColumn{&G, static_cast<unsigned int>(columns.size())});
      qr.solve(QTr, ATr, /*transpose=*/true);
      qr.solve(c, QTr);
      result = 0;
      if (fitted)
        *fitted = 0;
      for (unsigned int k = 0; k < used; ++k)
      {
        result.add(-c(k), kept[k]->dX);
        if (fitted)
          fitted->add(-c(k), kept[k]->dR);
      }
      return true;
    }

    /// The columns the filter keeps (newest first) and the pseudo-inverse of V = [dR_k]:
    /// V^+ x = (Z_k . x)_k with [Z_k] = V (V^T V)^-1 = V R^-1 R^-T.
    struct Secants
    {
      std::vector<VectorType> dR, dX, Z;
    };
    Secants kept_secants() const
    {
      const dealii::FullMatrix<double> G = gram(nullptr);
      dealii::ImplicitQR<internal::GramColumn> qr;
      const std::vector<const Columns*> kept = factorize(qr, G);
      Secants s;
      dealii::Vector<double> e(used), y(used), g(used);
      for (unsigned int i = 0; i < used; ++i)
      {
        s.dR.push_back(kept[i]->dR);
        s.dX.push_back(kept[i]->dX);
        // Column i of (R^T R)^-1: R^T y = e_i, R g = y.
        e = 0;
        e(i) = 1;
        qr.solve(y, e, /*transpose=*/true);
        qr.solve(g, y);
        VectorType z = kept[i]->dR;
        z = 0;
        for (unsigned int k = 0; k < used; ++k)
          z.add(g(k), kept[k]->dR);
        s.Z.push_back(z);
      }
      return s;
    }

    /// Save or load the columns (a checkpoint of the coupling; Boost serialization).
    template <class Archive>
    void serialize(Archive& ar, const unsigned int /*version*/)
    {
      ar& columns& used;
    }

  private:
    struct Columns
    {
      VectorType dR, dX;
      unsigned int tag;
      template <class Archive>
      void serialize(Archive& ar, const unsigned int /*version*/)
      {
        ar& dR& dX& tag;
      }
    };
    /// The Gram matrix of the columns dR_k (newest first) and, as the last row and column, `r`
    /// (if given): one MPI sum of this rank's products.
    dealii::FullMatrix<double> gram(const VectorType* r) const
    {
      using Traits = internal::GramTraits<VectorType>;
      std::vector<std::vector<dealii::Vector<double>>> parts;
      for (const auto& column : columns)
        parts.push_back(Traits::local(column.dR));
      if (r)
        parts.push_back(Traits::local(*r));
      const unsigned int n = parts.size();
      std::vector<double> products;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j <= i; ++j)
        {
          double local = 0;
          for (unsigned int b = 0; b < parts[i].size(); ++b)
            local += parts[i][b] * parts[j][b];
          products.push_back(local);
        }
      if (n > 0)
      {
        const MPI_Comm comm = Traits::comm(r ? *r : columns.front().dR);
        if (dealii::Utilities::MPI::n_mpi_processes(comm) > 1)
        {
          const std::vector<double> local = products;
          dealii::Utilities::MPI::sum(dealii::make_array_view(local), comm,
                                      dealii::make_array_view(products));
        }
      }
      dealii::FullMatrix<double> G(n, n);
      unsigned int k = 0;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j <= i; ++j, ++k)
          G(i, j) = G(j, i) = products[k];
      return G;
    }

    /// Append the columns newest first to `qr` (column k is row k of G), leaving out the ones
    /// the filter rejects; the kept ones, in the order of qr's columns (sets `used`).
    std::vector<const Columns*> factorize(dealii::ImplicitQR<internal::GramColumn>& qr,
                                          const dealii::FullMatrix<double>& G) const
    {
      const double filter2 = filter * filter;
      qr.connect_append_column_slot(
        [filter2](const dealii::Vector<double>&, const double& rho2, const double& norm2)
        { return rho2 > filter2 * norm2 && rho2 > 0; });
      std::vector<const Columns*> kept;
      unsigned int k = 0;
      for (auto column = columns.begin(); column != columns.end(); ++column, ++k)
        if (G(k, k) > 0 && qr.append_column(internal::GramColumn{&G, k}))
          kept.push_back(&*column);
      used = kept.size();
      return kept;
    }

    double filter;
    std::list<Columns> columns; ///< newest first
    std::list<Columns> spare;   ///< forgotten columns, their storage kept for reuse
    mutable unsigned int used = 0;
  };
} // namespace fvfsi
