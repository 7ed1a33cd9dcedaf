// The out-of-line Eigen kernels every translation unit would otherwise compile again for each of
// the suite's scalars: matrix-matrix and matrix-vector products (gebp, the packing routines,
// gemv), triangular solves and the LU factorisations. They are compiled once, in
// core/eigen_kernels.cpp (part of libgeomech), and declared `extern template` here, so a property
// file or a student's file only instantiates what is inlined. Same code, same flags: this changes
// build time, not results.
//
// Active where GEOMECH_EIGEN_KERNELS_PREBUILT is defined: by every target linking libgeomech (a
// PUBLIC definition) and by the student toolchain. A target that compiles core/ without the
// library (the fuzzers, a benchmark) instantiates the kernels itself as before.
//
// The template arguments follow Eigen 3.4's own choices (GeneralMatrixMatrix.h,
// TriangularSolverMatrix.h, GeneralMatrixVector.h), taken from its traits rather than spelled out,
// so another SIMD width still names the right specialisations. A specialisation the code never
// uses costs one compile in the library and nothing else.
#pragma once

#include "core/scalar.hpp"

#include <Eigen/Dense>

namespace gm::eigen_kernels {
template <class T>
using Traits = Eigen::internal::gebp_traits<T, T>;
template <class T, int Order>
using ConstMapper = Eigen::internal::const_blas_data_mapper<T, Eigen::Index, Order>;
template <class T>
using Mapper = Eigen::internal::blas_data_mapper<T, Eigen::Index, Eigen::ColMajor, 0, 1>;
template <class T>
using Dense = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
}  // namespace gm::eigen_kernels

// GM_EIGEN_KERNELS(extern, T) declares, GM_EIGEN_KERNELS(, T) defines, the instantiations for T.
#define GM_EIGEN_KERNELS(EXTERN, T)                                                                                    \
  EXTERN template void Eigen::PartialPivLU<gm::eigen_kernels::Dense<T>>::compute();                                    \
  EXTERN template void Eigen::FullPivLU<gm::eigen_kernels::Dense<T>>::computeInPlace();                                \
  EXTERN template struct Eigen::internal::gebp_kernel<T, T, Eigen::Index, gm::eigen_kernels::Mapper<T>,                \
                                                      gm::eigen_kernels::Traits<T>::mr,                                \
                                                      gm::eigen_kernels::Traits<T>::nr, false, false>;                 \
  EXTERN template struct Eigen::internal::gemm_pack_lhs<                                                               \
      T, Eigen::Index, gm::eigen_kernels::ConstMapper<T, Eigen::ColMajor>, gm::eigen_kernels::Traits<T>::mr,           \
      gm::eigen_kernels::Traits<T>::LhsProgress, typename gm::eigen_kernels::Traits<T>::LhsPacket4Packing,             \
      Eigen::ColMajor>;                                                                                                \
  EXTERN template struct Eigen::internal::gemm_pack_lhs<                                                               \
      T, Eigen::Index, gm::eigen_kernels::ConstMapper<T, Eigen::RowMajor>, gm::eigen_kernels::Traits<T>::mr,           \
      gm::eigen_kernels::Traits<T>::LhsProgress, typename gm::eigen_kernels::Traits<T>::LhsPacket4Packing,             \
      Eigen::RowMajor>;                                                                                                \
  EXTERN template struct Eigen::internal::gemm_pack_rhs<T, Eigen::Index,                                               \
                                                        gm::eigen_kernels::ConstMapper<T, Eigen::ColMajor>,            \
                                                        gm::eigen_kernels::Traits<T>::nr, Eigen::ColMajor>;            \
  EXTERN template struct Eigen::internal::gemm_pack_rhs<                                                               \
      T, Eigen::Index, gm::eigen_kernels::Mapper<T>, gm::eigen_kernels::Traits<T>::nr, Eigen::ColMajor, false, true>;  \
  EXTERN template struct Eigen::internal::general_matrix_vector_product<                                               \
      Eigen::Index, T, gm::eigen_kernels::ConstMapper<T, Eigen::ColMajor>, Eigen::ColMajor, false, T,                  \
      gm::eigen_kernels::ConstMapper<T, Eigen::ColMajor>, false, 0>;                                                   \
  EXTERN template struct Eigen::internal::general_matrix_vector_product<                                               \
      Eigen::Index, T, gm::eigen_kernels::ConstMapper<T, Eigen::ColMajor>, Eigen::ColMajor, false, T,                  \
      gm::eigen_kernels::ConstMapper<T, Eigen::RowMajor>, false, 0>;                                                   \
  EXTERN template struct Eigen::internal::general_matrix_vector_product<                                               \
      Eigen::Index, T, gm::eigen_kernels::ConstMapper<T, Eigen::RowMajor>, Eigen::RowMajor, false, T,                  \
      gm::eigen_kernels::ConstMapper<T, Eigen::ColMajor>, false, 0>;                                                   \
  EXTERN template struct Eigen::internal::triangular_solve_matrix<T, Eigen::Index, Eigen::OnTheLeft, Eigen::UnitLower, \
                                                                  false, Eigen::ColMajor, Eigen::ColMajor, 1>;         \
  EXTERN template struct Eigen::internal::triangular_solve_matrix<T, Eigen::Index, Eigen::OnTheLeft, Eigen::Upper,     \
                                                                  false, Eigen::ColMajor, Eigen::ColMajor, 1>

// Naming Eigen's packet types (__m128d) as template arguments makes GCC warn that their
// alignment attributes are ignored; Eigen silences the same warning inside its own headers.
#define GM_EIGEN_KERNELS_QUIET_BEGIN \
  _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic ignored \"-Wignored-attributes\"")
#define GM_EIGEN_KERNELS_QUIET_END _Pragma("GCC diagnostic pop")

#ifdef GEOMECH_EIGEN_KERNELS_PREBUILT
GM_EIGEN_KERNELS_QUIET_BEGIN
GM_EIGEN_KERNELS(extern, double);
GM_EIGEN_KERNELS(extern, gm::Real50);
GM_EIGEN_KERNELS(extern, gm::Rational);
GM_EIGEN_KERNELS_QUIET_END
#endif
