//! Isotropic linear elastic materials and the 2D constitutive matrices.

/// Isotropic linear elastic material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Young's modulus E, MPa.
    pub young: f64,
    /// Poisson's ratio ν, dimensionless, −1 < ν < 0.5.
    pub poisson: f64,
}

/// The 2D idealisation of the out-of-plane direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Analysis {
    /// σ_yy = 0: thin plates; `thickness` in mm.
    PlaneStress {
        /// Thickness, mm.
        thickness: f64,
    },
    /// ε_yy = 0: long bodies; forces are reported for a slice of `thickness` mm.
    PlaneStrain {
        /// Thickness of the reported slice, mm.
        thickness: f64,
    },
}

impl Analysis {
    /// Out-of-plane thickness t, mm: every area integral is multiplied by it.
    pub fn thickness(&self) -> f64 {
        match *self {
            Analysis::PlaneStress { thickness } | Analysis::PlaneStrain { thickness } => thickness,
        }
    }
}

impl Material {
    /// Lamé parameters (λ, μ), MPa.
    pub fn lame_parameters(&self) -> (f64, f64) {
        let (e, nu) = (self.young, self.poisson);
        (
            e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)),
            e / (2.0 * (1.0 + nu)),
        )
    }

    /// Constitutive matrix D (MPa) with σ = D ε for the strain vector (ε_xx, ε_zz, γ_xz).
    pub fn constitutive(&self, analysis: Analysis) -> [[f64; 3]; 3] {
        let (e, nu) = (self.young, self.poisson);
        let (d11, d12, d33) = match analysis {
            Analysis::PlaneStress { .. } => {
                let c = e / (1.0 - nu * nu);
                (c, c * nu, c * (1.0 - nu) / 2.0)
            }
            Analysis::PlaneStrain { .. } => {
                let (lambda, mu) = self.lame_parameters();
                (lambda + 2.0 * mu, lambda, mu)
            }
        };
        [[d11, d12, 0.0], [d12, d11, 0.0], [0.0, 0.0, d33]]
    }

    /// Effective modulus E* of the 2D idealisation (MPa): E for plane stress, E/(1−ν²) for plane
    /// strain; the modulus that enters Hertz's line-contact formula.
    pub fn effective_modulus(&self, analysis: Analysis) -> f64 {
        match analysis {
            Analysis::PlaneStress { .. } => self.young,
            Analysis::PlaneStrain { .. } => self.young / (1.0 - self.poisson * self.poisson),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_strain_matches_lame_form() {
        let m = Material {
            young: 2.0e5,
            poisson: 0.3,
        };
        let d = m.constitutive(Analysis::PlaneStrain { thickness: 1.0 });
        let (l, mu) = m.lame_parameters();
        // Exact algebra: only round-off of a few operations.
        assert!((d[0][0] - (l + 2.0 * mu)).abs() < 1e-9 * d[0][0]);
        assert!((d[2][2] - m.young / (2.0 * 1.3)).abs() < 1e-9 * d[2][2]);
    }

    #[test]
    fn plane_stress_uniaxial_gives_young() {
        let m = Material {
            young: 1.3e5,
            poisson: 0.23,
        };
        let d = m.constitutive(Analysis::PlaneStress { thickness: 10.0 });
        // σ_zz = 0 ⇒ ε_zz = −ν ε_xx ⇒ σ_xx = E ε_xx.
        let sxx = d[0][0] - d[0][1] * d[1][0] / d[1][1];
        assert!((sxx - m.young).abs() < 1e-9 * m.young);
    }
}
