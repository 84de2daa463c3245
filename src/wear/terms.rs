//! The wear of one half period at every contact point, W_i(p) = Σ_l c_l,i p^b_l (mm, p in
//! MPa), as the step loop and the steady solver use it ([`crate::wear::law`] works on one
//! point's terms).
//!
//! In a plane problem every point slides the same distance, so the terms are the same at
//! every point and are stored once. On bodies of revolution turning about their axis a point
//! at radius r slides at ω r, and its terms are c_l r^a_l ([`crate::wear::AxisRotation`]):
//! stored per point, read through the same [`WearTerms::at`].

/// W_i(p) = Σ_l c_l,i p^b_l at every contact point: (c, b) pairs, c in mm MPa⁻ᵇ.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct WearTerms {
    /// (c, b) per law: once for every point, or `laws` of them per point in turn.
    values: Vec<(f64, f64)>,
    /// Number of wear laws (terms per point).
    laws: usize,
    /// Whether `values` holds each point's own terms.
    per_point: bool,
}

impl WearTerms {
    /// The same terms at every point.
    pub fn uniform(terms: &[(f64, f64)]) -> WearTerms {
        WearTerms {
            values: terms.to_vec(),
            laws: terms.len(),
            per_point: false,
        }
    }

    /// Terms `terms` scaled point by point: law l at point i is (c_l · `factor[l][i]`, b_l).
    /// `factor` has one row per law, each as long as the contact has points.
    pub fn scaled_per_point(terms: &[(f64, f64)], factor: &[Vec<f64>]) -> WearTerms {
        let points = factor.first().map_or(0, Vec::len);
        let values = (0..points)
            .flat_map(|i| {
                terms
                    .iter()
                    .zip(factor)
                    .map(move |(&(c, b), f)| (c * f[i], b))
            })
            .collect();
        WearTerms {
            values,
            laws: terms.len(),
            per_point: true,
        }
    }

    /// The terms at point `i`.
    pub fn at(&self, i: usize) -> &[(f64, f64)] {
        if self.per_point {
            &self.values[i * self.laws..(i + 1) * self.laws]
        } else {
            &self.values
        }
    }

    /// Whether the terms differ from point to point.
    pub fn is_per_point(&self) -> bool {
        self.per_point
    }

    /// Whether no point wears (every c zero).
    pub fn none_wear(&self) -> bool {
        self.values.iter().all(|t| t.0 == 0.0)
    }

    /// Whether the law is concave ([`crate::wear::law::is_concave`]) at some point; the
    /// exponents are the same at every point, so where it is concave anywhere it is concave
    /// wherever the point wears.
    pub fn is_concave(&self) -> bool {
        let points = if self.per_point {
            self.values.len() / self.laws.max(1)
        } else {
            1
        };
        (0..points).any(|i| super::law::is_concave(self.at(i)))
    }

    /// Whether some term's exponent differs from 1.
    pub fn is_nonlinear(&self) -> bool {
        self.values.iter().any(|t| t.1 != 1.0)
    }

    /// The same terms with every c multiplied by `scale`.
    pub fn scaled(&self, scale: f64) -> WearTerms {
        WearTerms {
            values: self.values.iter().map(|&(c, b)| (scale * c, b)).collect(),
            ..self.clone()
        }
    }

    /// Every c replaced by `f(c, b)`, the exponents kept.
    pub fn map(&self, f: impl Fn(f64, f64) -> (f64, f64)) -> WearTerms {
        WearTerms {
            values: self.values.iter().map(|&(c, b)| f(c, b)).collect(),
            ..self.clone()
        }
    }
}

impl From<&[(f64, f64)]> for WearTerms {
    fn from(terms: &[(f64, f64)]) -> WearTerms {
        WearTerms::uniform(terms)
    }
}

impl From<&Vec<(f64, f64)>> for WearTerms {
    fn from(terms: &Vec<(f64, f64)>) -> WearTerms {
        WearTerms::uniform(terms)
    }
}

impl<const N: usize> From<&[(f64, f64); N]> for WearTerms {
    fn from(terms: &[(f64, f64); N]) -> WearTerms {
        WearTerms::uniform(terms)
    }
}

impl From<&WearTerms> for WearTerms {
    fn from(terms: &WearTerms) -> WearTerms {
        terms.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn per_point_terms_scale_each_law_by_its_own_factor() {
        let terms = [(2.0, 1.0), (3.0, 2.0)];
        let factor = vec![vec![1.0, 0.5], vec![4.0, 0.25]];
        let t = WearTerms::scaled_per_point(&terms, &factor);
        assert_eq!(t.at(0), &[(2.0, 1.0), (12.0, 2.0)]);
        assert_eq!(t.at(1), &[(1.0, 1.0), (0.75, 2.0)]);
        let u = WearTerms::uniform(&terms);
        assert_eq!(u.at(0), u.at(7));
        assert!(!u.is_per_point() && t.is_per_point());
    }
}
