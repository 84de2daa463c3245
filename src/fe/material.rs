//! Isotropic linear elastic materials and the 2D constitutive matrices; the thermal properties
//! of the heat stage ([`ThermalMaterial`]) and the thermal stress they cause.

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
    /// A body of revolution: x is the radius r ≥ 0, z the axis, and the hoop strain u_r/r
    /// joins the plane ones; integrals are over the whole circle (2πr), so forces are in N
    /// for the whole circumference.
    Axisymmetric,
}

impl Analysis {
    /// Out-of-plane thickness t of a plane analysis, mm (None for an axisymmetric one, whose
    /// out-of-plane measure 2πr changes from point to point: [`Analysis::weight`]).
    pub fn thickness(&self) -> Option<f64> {
        match *self {
            Analysis::PlaneStress { thickness } | Analysis::PlaneStrain { thickness } => {
                Some(thickness)
            }
            Analysis::Axisymmetric => None,
        }
    }

    /// What an area (or line) integral is multiplied by at the point `x` (mm): the
    /// thickness t of a plane analysis, the circumference 2πr (r = `x[0]`) of an axisymmetric
    /// one.
    pub fn weight(&self, x: [f64; 2]) -> f64 {
        match *self {
            Analysis::PlaneStress { thickness } | Analysis::PlaneStrain { thickness } => thickness,
            Analysis::Axisymmetric => std::f64::consts::TAU * x[0],
        }
    }

    /// Whether the hoop strain u_r/r is part of the strain (axisymmetric).
    pub fn is_axisymmetric(&self) -> bool {
        matches!(self, Analysis::Axisymmetric)
    }
}

/// How close to the axis (relative to the body's size, its largest |coordinate|) a point of a
/// body of revolution counts as on it: held radially, a contact point without a ring, its
/// hoop strain ∂u_r/∂r. One tolerance for all three (a review found three, and a ball whose
/// axis was 1e-7 mm off r = 0, as CAD meshes give, pressed 10 % too hard in silence).
pub const AXIS_TOLERANCE: f64 = 1e-6;

/// Whether radius `r` (mm) of a body of size `size` (mm) lies on the axis.
pub fn on_axis(r: f64, size: f64) -> bool {
    r.abs() <= AXIS_TOLERANCE * size.max(f64::MIN_POSITIVE)
}

impl Analysis {}

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
            // An axisymmetric body's in-plane part is plane strain's; its hoop couplings are
            // [`Material::hoop_coupling`].
            Analysis::PlaneStrain { .. } | Analysis::Axisymmetric => {
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
            Analysis::PlaneStrain { .. } | Analysis::Axisymmetric => {
                self.young / (1.0 - self.poisson * self.poisson)
            }
        }
    }

    /// The axisymmetric constitutive law's hoop part (MPa): σ_θθ = λ (ε_rr + ε_zz) +
    /// (λ + 2μ) ε_θθ, and ε_θθ adds λ ε_θθ to σ_rr and σ_zz. Returns (λ, λ + 2μ).
    pub fn hoop_coupling(&self) -> (f64, f64) {
        let (lambda, mu) = self.lame_parameters();
        (lambda, lambda + 2.0 * mu)
    }
}

/// Thermal properties of a material in the model's units (mm, s, mJ, mW, K). A problem file
/// gives them in the units engineers use, and [`ThermalMaterial::from_engineering`] converts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThermalMaterial {
    /// Conductivity k, mW/(mm·K) (numerically equal to W/(m·K)).
    pub conductivity: f64,
    /// Heat capacity per unit volume ρc, mJ/(mm³·K).
    pub heat_capacity: f64,
    /// Linear thermal expansion coefficient α, 1/K.
    pub expansion: f64,
}

impl ThermalMaterial {
    /// From a conductivity in W/(m·K), a specific heat in J/(kg·K), a density in kg/m³ and an
    /// expansion coefficient in 1/K. W/(m·K) = 10³ mW / (10³ mm · K) is the same number in
    /// mW/(mm·K); J/(kg·K) · kg/m³ = J/(m³·K) = 10³ mJ / (10⁹ mm³ · K), hence the 10⁻⁶.
    pub fn from_engineering(
        conductivity: f64,
        specific_heat: f64,
        density: f64,
        expansion: f64,
    ) -> ThermalMaterial {
        ThermalMaterial {
            conductivity,
            heat_capacity: specific_heat * density * 1e-6,
            expansion,
        }
    }

    /// Thermal diffusivity k/(ρc), mm²/s.
    pub fn diffusivity(&self) -> f64 {
        self.conductivity / self.heat_capacity
    }

    /// Thermal effusivity √(k ρc), mW·s^½/(mm²·K): how two bodies pressed together share a
    /// heat source at their interface in a short contact (Blok's partition).
    pub fn effusivity(&self) -> f64 {
        (self.conductivity * self.heat_capacity).sqrt()
    }
}

/// A heat transfer coefficient in W/(m²·K) in the model's mW/(mm²·K): 10³ mW / (10⁶ mm² · K).
pub fn film_coefficient(watts_per_square_metre_kelvin: f64) -> f64 {
    watts_per_square_metre_kelvin * 1e-3
}

impl Material {
    /// The stress (σ_xx, σ_zz, σ_xz) a free thermal strain of one kelvin would need to be held
    /// back (MPa/K): D m α′ with m = (1, 1, 0) and α′ the in-plane free strain per kelvin, α
    /// in plane stress (the body expands freely out of its plane) and (1 + ν) α in plane strain
    /// (ε_yy = 0 holds the out-of-plane expansion back, which pushes the plane outwards through
    /// Poisson's effect). This is E α/(1 − ν) and E α/(1 − 2ν) on the diagonal.
    pub fn thermal_stress_per_kelvin(&self, analysis: Analysis, expansion: f64) -> [f64; 3] {
        let free_strain = match analysis {
            Analysis::PlaneStress { .. } => expansion,
            Analysis::PlaneStrain { .. } | Analysis::Axisymmetric => {
                (1.0 + self.poisson) * expansion
            }
        };
        let d = self.constitutive(analysis);
        [
            (d[0][0] + d[0][1]) * free_strain,
            (d[1][0] + d[1][1]) * free_strain,
            0.0,
        ]
    }

    /// The in-plane free thermal strain per kelvin (α or (1 + ν) α, see
    /// [`Material::thermal_stress_per_kelvin`]), 1/K.
    pub fn free_thermal_strain(&self, analysis: Analysis, expansion: f64) -> f64 {
        match analysis {
            Analysis::PlaneStress { .. } => expansion,
            Analysis::PlaneStrain { .. } | Analysis::Axisymmetric => {
                (1.0 + self.poisson) * expansion
            }
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

    #[test]
    fn thermal_stress_coefficients() {
        let m = Material {
            young: 2.0e5,
            poisson: 0.3,
        };
        let alpha = 1.2e-5;
        // Closed forms: E α/(1 − ν) (plane stress) and E α/(1 − 2ν) (plane strain); a few
        // operations of round-off.
        let s = m.thermal_stress_per_kelvin(Analysis::PlaneStress { thickness: 1.0 }, alpha);
        assert!((s[0] - 2.0e5 * alpha / 0.7).abs() < 1e-12 * s[0]);
        let s = m.thermal_stress_per_kelvin(Analysis::PlaneStrain { thickness: 1.0 }, alpha);
        assert!((s[1] - 2.0e5 * alpha / 0.4).abs() < 1e-12 * s[1]);
        assert_eq!(s[2], 0.0);
    }

    #[test]
    fn engineering_units() {
        // Steel: 50 W/(m·K), 460 J/(kg·K), 7800 kg/m³ → ρc = 3.588 mJ/(mm³·K), a = 13.94 mm²/s.
        let t = ThermalMaterial::from_engineering(50.0, 460.0, 7800.0, 1.2e-5);
        assert!((t.heat_capacity - 3.588).abs() < 1e-12);
        assert!((t.diffusivity() - 50.0 / 3.588).abs() < 1e-12);
        assert!((film_coefficient(25.0) - 0.025).abs() < 1e-15);
    }
}
