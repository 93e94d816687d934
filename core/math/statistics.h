// SPDX-License-Identifier: MIT
// Distribution functions and multiple-testing control for the statistical image comparison.
#pragma once

#include <vector>

namespace rt {

/// Regularised incomplete beta function I_x(a, b) (continued fraction, Lentz's method).
double incompleteBeta(double a, double b, double x);

/// P(T <= t) for Student's t with `dof` degrees of freedom; dof = inf gives the normal CDF.
double studentTCdf(double t, double dof);

/// Regularized upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a).
double upperIncompleteGamma(double a, double x);

/// Survival function of the chi-square distribution: P(X >= x) with `dof` degrees of freedom.
double chiSquareSf(double x, double dof);

/// Two-sided p-value of a t statistic: P(|T| >= |t|).
double twoSidedPValue(double t, double dof);

/// The t with P(T <= t) = p (bisection on the CDF; 0 < p < 1).
double studentTQuantile(double p, double dof);

/// Benjamini-Hochberg: which of the hypotheses with p-values `p` are rejected while keeping the
/// false discovery rate at `q`. Under the global null (all hypotheses true) and independent
/// tests this also bounds the chance of any rejection by q (Simes).
std::vector<bool> benjaminiHochberg(const std::vector<double> &p, double q);

}  // namespace rt
