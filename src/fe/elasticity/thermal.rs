//! Thermal strain as a load on a body: the temperature field of the heat stage
//! ([`crate::conduction`]) expands each element, σ = D (ε − ε_th) with ε_th = α′ ΔT (1, 1, 0)
//! (α′ = α in plane stress, (1 + ν) α in plane strain, [`Material::thermal_stress_per_kelvin`]),
//! so the load is f_a = t ∫ B_aᵀ D ε_th dA = t ∫ B_aᵀ s ΔT dA with s = D m α′.
//!
//! Per element, over the temperature's modes b (the same degree; its own space, which may have
//! fewer internal modes than the displacement's, [`crate::basis::Space`]):
//! F[(2a + c), b] = t ∫ ∂N_a/∂x_c s_c N_b dA. The internal displacement modes are condensed
//! as the stiffness was: the boundary load is (F_b − Rᵀ F_i) ΔT and the internal modes are
//! recovered as u_i = K_ii⁻¹ F_i ΔT − R u_b. Both matrices are kept per element type (equal
//! geometry up to a translation, material and quadrature), as the stiffness is.

use super::{element_stiffness, ElasticBody};
use crate::basis::{QuadBasis, Space};
use crate::material::Material;
use crate::quadrature::gauss_legendre;
use faer::linalg::solvers::Solve;
use faer::{Mat, Side};
use std::collections::HashMap;

/// The thermal load operators of one body.
#[derive(Clone, Debug)]
pub struct ThermalLoads {
    /// Per pair of element type and temperature space: the condensed boundary load per unit
    /// ΔT mode, (F_b − Rᵀ F_i) (N/K, 2·4p × the temperature's modes), and the internal
    /// response K_ii⁻¹ F_i (mm/K).
    types: Vec<(Mat<f64>, Mat<f64>)>,
    /// Per element: its entry of `types`.
    type_of: Vec<usize>,
    /// Expansion coefficient α (1/K) of each material.
    pub expansion: Vec<f64>,
    /// The temperature's bases at the displacement's degree: tensor-product and trunk.
    temperature_bases: [QuadBasis; 2],
    /// Per element: the temperature's space (index into `temperature_bases`).
    space_of: Vec<usize>,
}

impl ThermalLoads {
    /// The temperature's basis on `element` (its modes are the columns of the element's load).
    pub fn temperature_basis(&self, element: usize) -> &QuadBasis {
        &self.temperature_bases[self.space_of[element]]
    }

    /// The entry of `element` among the loads of distinct elements (elements of equal
    /// geometry, material, quadrature and temperature space share one).
    pub fn load_type(&self, element: usize) -> usize {
        self.type_of[element]
    }
}

/// F of one element (2 n_modes × n_modes), N/K.
fn coupling_matrix(
    body: &ElasticBody,
    temperature_basis: &QuadBasis,
    element: usize,
    material: &Material,
    alpha: f64,
) -> Mat<f64> {
    let mesh = &body.mesh;
    let basis = &body.basis;
    let nq = super::quadrature_points(mesh, element, basis.p);
    let rule = gauss_legendre(nq);
    let tab = basis.tabulate(&rule.points, &rule.points);
    let temperature = temperature_basis.tabulate(&rule.points, &rule.points);
    let n = basis.n_modes();
    let n_temperature = temperature_basis.n_modes();
    let s = material.thermal_stress_per_kelvin(body.analysis, alpha);
    // Heat needs contact, which axisymmetric bodies do not have yet (refused with it).
    let t = body
        .analysis
        .thickness()
        .expect("contact, and with it heat, is refused for axisymmetric bodies");
    // F = Σ_q (∇N_a s w)_q N_b(q): the gradients' column (2n values) and the values' column
    // (n) of each quadrature point, then one dense product; summed entry by entry, with
    // the matrix's strided writes, it cost as much as the rest of the heat's elastic set-up.
    let points = nq * nq;
    let mut gradients = Mat::<f64>::zeros(2 * n, points);
    let mut values = Mat::<f64>::zeros(n_temperature, points);
    for iy in 0..nq {
        for ix in 0..nq {
            let q = iy * nq + ix;
            let (j, det) = mesh.jacobian(element, rule.points[ix], rule.points[iy]);
            let w = rule.weights[ix] * rule.weights[iy] * det * t;
            let (dxi_dx, dxi_dz) = (j[1][1] / det, -j[0][1] / det);
            let (deta_dx, deta_dz) = (-j[1][0] / det, j[0][0] / det);
            for a in 0..n {
                let idx = a * tab.n_points + q;
                let (nxi, neta) = (tab.d_xi[idx], tab.d_eta[idx]);
                gradients[(2 * a, q)] = (nxi * dxi_dx + neta * deta_dx) * s[0] * w;
                gradients[(2 * a + 1, q)] = (nxi * dxi_dz + neta * deta_dz) * s[1] * w;
            }
            for b in 0..n_temperature {
                values[(b, q)] = temperature.values[b * temperature.n_points + q];
            }
        }
    }
    gradients * values.transpose()
}

impl ElasticBody {
    /// The thermal load operators of this body for the expansion coefficients `expansion`
    /// (1/K, one per material) and a temperature at the body's degree in the space
    /// `temperature_spaces[e]` on element e. Recomputes each element type's stiffness once
    /// (its internal block is needed to condense the load).
    pub fn thermal_loads(
        &self,
        expansion: &[f64],
        temperature_spaces: &[Space],
    ) -> Result<ThermalLoads, super::ElasticityError> {
        let temperature_bases = [
            QuadBasis::new(self.basis.p, Space::TensorProduct),
            QuadBasis::new(self.basis.p, Space::Trunk),
        ];
        let space_of: Vec<usize> = (0..self.mesh.elements.len())
            .map(|e| usize::from(temperature_spaces.get(e) == Some(&Space::Trunk)))
            .collect();
        let nb = 2 * self.basis.n_boundary();
        let mut types = Vec::new();
        let mut first_of: HashMap<(usize, usize), usize> = HashMap::new();
        let mut type_of = Vec::with_capacity(self.mesh.elements.len());
        for element in 0..self.mesh.elements.len() {
            let key = (self.element_type[element], space_of[element]);
            if let Some(&t) = first_of.get(&key) {
                type_of.push(t);
                continue;
            }
            first_of.insert(key, types.len());
            type_of.push(types.len());
            let m = self.mesh.elements[element].material;
            let material = &self.materials[m];
            let temperature_basis = &temperature_bases[space_of[element]];
            let f = coupling_matrix(self, temperature_basis, element, material, expansion[m]);
            let n = f.nrows();
            let ni = n - nb;
            let condensed_recovery = &self.types[key.0].recovery;
            let (load, internal) = if ni == 0 {
                (f.clone(), Mat::zeros(0, f.ncols()))
            } else {
                let nq = super::quadrature_points(&self.mesh, element, self.basis.p);
                let k = element_stiffness(
                    &self.mesh,
                    element,
                    &self.basis,
                    material,
                    self.analysis,
                    nq,
                );
                let kii = k.submatrix(nb, nb, ni, ni);
                let fi = f.submatrix(nb, 0, ni, f.ncols());
                let internal = kii
                    .llt(Side::Lower)
                    .map_err(|_| super::ElasticityError::Internal { element })?
                    .solve(fi);
                let load = f.submatrix(0, 0, nb, f.ncols()) - condensed_recovery.transpose() * fi;
                (load, internal)
            };
            types.push((load, internal));
        }
        Ok(ThermalLoads {
            types,
            type_of,
            expansion: expansion.to_vec(),
            temperature_bases,
            space_of,
        })
    }

    /// The thermal stress s ΔT (MPa) of a rise `rise` (K) in `element`: what
    /// [`ElasticBody::values_at_reference`]'s D ε must be reduced by where the body is heated.
    pub fn thermal_stress(&self, loads: &ThermalLoads, element: usize, rise: f64) -> [f64; 3] {
        let m = self.mesh.elements[element].material;
        let s = self.materials[m].thermal_stress_per_kelvin(self.analysis, loads.expansion[m]);
        [s[0] * rise, s[1] * rise, 0.0]
    }

    /// The condensed global load (N per global boundary dof) of a temperature rise whose
    /// coefficients on element e's modes (signs applied, K) are `rise(e)`.
    pub fn thermal_load_vector(
        &self,
        loads: &ThermalLoads,
        rise: impl Fn(usize) -> Vec<f64>,
    ) -> Vec<f64> {
        let mut load = vec![0.0; self.dofs.n_dofs()];
        for element in 0..self.mesh.elements.len() {
            let dt = rise(element);
            let ed = self.dofs.element_dofs(&self.mesh, element);
            let f = &loads.types[loads.type_of[element]].0;
            for (r, (&g, &s)) in ed.global.iter().zip(&ed.sign).enumerate() {
                let v: f64 = (0..f.ncols()).map(|b| f[(r, b)] * dt[b]).sum();
                load[g] += s * v;
            }
        }
        load
    }

    /// The displacement of `boundary` (the solution of a load that included the thermal
    /// load of `rise`) with its internal modes recovered: u_i = K_ii⁻¹ F_i ΔT − R u_b.
    pub fn recover_thermal(
        &self,
        boundary: Vec<f64>,
        loads: &ThermalLoads,
        rise: impl Fn(usize) -> Vec<f64>,
    ) -> super::Displacement {
        let mut u = self.recover(boundary);
        let nb = 2 * self.basis.n_boundary();
        for (element, local) in u.local.iter_mut().enumerate() {
            let z = &loads.types[loads.type_of[element]].1;
            if z.nrows() == 0 {
                continue;
            }
            let dt = rise(element);
            for i in 0..z.nrows() {
                local[nb + i] += (0..z.ncols()).map(|b| z[(i, b)] * dt[b]).sum::<f64>();
            }
        }
        u
    }

    /// The condensed boundary load per unit temperature mode of `element` (N/K, rows in the
    /// order of [`crate::dofs::DofMap::element_dofs`] without signs, columns the
    /// temperature's modes without signs).
    pub fn thermal_load_matrix<'a>(&self, loads: &'a ThermalLoads, element: usize) -> &'a Mat<f64> {
        &loads.types[loads.type_of[element]].0
    }
}

#[cfg(test)]
mod tests {
    use crate::basis::{ModeKind, Space};
    use crate::elasticity::{Constraints, Discretisation, ElasticBody};
    use crate::geometry::{Block, EdgeShape};
    use crate::material::{Analysis, Material};
    use crate::mesh::{Mesh, MeshBlock};

    const STEEL: Material = Material {
        young: 2.0e5,
        poisson: 0.3,
    };
    const ALPHA: f64 = 1.2e-5;

    /// A 60 × 8 mm strip, 6 × 2 elements (the middle line z = 4 a mesh line), held at
    /// (0, 4) in x and z and at (60, 4) in z: free of any stress a compatible strain causes.
    fn strip(analysis: Analysis, p: usize) -> ElasticBody {
        let block = MeshBlock {
            block: Block::new(
                [[0.0, 0.0], [60.0, 0.0], [60.0, 8.0], [0.0, 8.0]],
                [
                    EdgeShape::Straight,
                    EdgeShape::Straight,
                    EdgeShape::Straight,
                    EdgeShape::Straight,
                ],
            )
            .unwrap(),
            u_lines: (0..=6).map(|i| i as f64 / 6.0).collect(),
            v_lines: vec![0.0, 0.5, 1.0],
            material: 0,
            edge_names: [None, None, None, None],
        };
        let mesh = Mesh::build(vec![block]).unwrap();
        let dofs = crate::dofs::DofMap::new(&mesh, p);
        let left = mesh.vertex_at([0.0, 4.0]).unwrap();
        let right = mesh.vertex_at([60.0, 4.0]).unwrap();
        let fixed = vec![
            dofs.vertex_dof(left, 0),
            dofs.vertex_dof(left, 1),
            dofs.vertex_dof(right, 1),
        ];
        ElasticBody::new(
            "strip",
            mesh,
            vec![STEEL],
            analysis,
            Discretisation {
                p,
                space: Space::TensorProduct,
            },
            &Constraints {
                fixed,
                ..Default::default()
            },
        )
        .unwrap()
    }

    /// The rise's coefficients on each element's temperature modes for a field linear in x
    /// and z: the vertex values (a linear field is linear along every straight edge: no edge
    /// modes).
    fn linear_rise<'a>(
        body: &'a ElasticBody,
        loads: &'a super::ThermalLoads,
        field: impl Fn([f64; 2]) -> f64 + 'a,
    ) -> impl Fn(usize) -> Vec<f64> + 'a {
        move |element| {
            let vertices = body.mesh.elements[element].vertices;
            loads
                .temperature_basis(element)
                .modes
                .iter()
                .map(|m| match m.kind {
                    ModeKind::Vertex(v) => field(body.mesh.vertices[vertices[v]]),
                    _ => 0.0,
                })
                .collect()
        }
    }

    /// The displacement of a temperature `field` (linear) in the displacement's space.
    fn solve(
        body: &ElasticBody,
        field: impl Fn([f64; 2]) -> f64 + Copy,
    ) -> crate::elasticity::Displacement {
        solve_in(
            body,
            field,
            &vec![body.basis.space; body.mesh.elements.len()],
        )
    }

    /// The same with the temperature in `spaces` (one per element).
    fn solve_in(
        body: &ElasticBody,
        field: impl Fn([f64; 2]) -> f64 + Copy,
        spaces: &[Space],
    ) -> crate::elasticity::Displacement {
        let loads = body.thermal_loads(&[ALPHA], spaces).unwrap();
        let load = body.thermal_load_vector(&loads, linear_rise(body, &loads, field));
        let mut rhs = faer::Mat::from_fn(load.len(), 1, |i, _| load[i]);
        body.solve_in_place(&mut rhs).unwrap();
        let boundary = (0..load.len()).map(|i| rhs[(i, 0)]).collect();
        body.recover_thermal(boundary, &loads, linear_rise(body, &loads, field))
    }

    #[test]
    fn uniform_rise_expands_freely() {
        // Closed form (c): a free body heated uniformly by ΔT expands by α′ΔT in every
        // direction, u = α′ΔT (x − x₀), with α′ = α (plane stress) or (1 + ν) α (plane
        // strain), and is free of stress. The field is linear: exact in the space, so only
        // round-off (1e-10 of the displacement, the bound) remains.
        let rise = 50.0;
        for (analysis, free) in [
            (Analysis::PlaneStress { thickness: 10.0 }, ALPHA),
            (Analysis::PlaneStrain { thickness: 10.0 }, 1.3 * ALPHA),
        ] {
            for p in [1, 3, 8] {
                let body = strip(analysis, p);
                let u = solve(&body, |_| rise);
                let loads = body
                    .thermal_loads(&[ALPHA], &vec![body.basis.space; body.mesh.elements.len()])
                    .unwrap();
                for x in [[60.0, 4.0], [30.0, 0.0], [45.0, 8.0], [7.0, 1.0]] {
                    let v = body.values_at(&u, x).unwrap();
                    let exact = [free * rise * x[0], free * rise * (x[1] - 4.0)];
                    let scale = free * rise * 60.0;
                    for c in 0..2 {
                        assert!(
                            (v.displacement[c] - exact[c]).abs() < 1e-10 * scale,
                            "{analysis:?} p = {p} {x:?}: {:?} vs {exact:?}",
                            v.displacement
                        );
                    }
                    let (element, ..) = body.mesh.locate(x).unwrap();
                    let s = body.thermal_stress(&loads, element, rise);
                    for c in 0..3 {
                        // σ = D ε − s ΔT vanishes: measured against s ΔT itself.
                        let sigma = v.stress[c] - s[c];
                        assert!(sigma.abs() < 1e-9 * s[0].abs(), "{sigma}");
                    }
                }
            }
        }
    }

    #[test]
    fn gradient_through_the_thickness_bends_a_free_strip() {
        // Closed form (d): a free strip whose temperature rises linearly through its
        // thickness, ΔT = b (z − 4), bends stress-free to the curvature κ = α′ b (its
        // thermal strain is compatible): u_z(x, 4) = α′ b x (60 − x)/2 between the supports at
        // the ends of its middle line. u_z is quadratic: exact from p = 2, so round-off only
        // (1e-9 of the sag; the issue asks 0.1 %).
        let b = 5.0; // K/mm: 40 K between the faces
        for (analysis, free) in [
            (Analysis::PlaneStress { thickness: 10.0 }, ALPHA),
            (Analysis::PlaneStrain { thickness: 10.0 }, 1.3 * ALPHA),
        ] {
            for p in [2, 6] {
                let body = strip(analysis, p);
                // The temperature in the displacement's space, and with every other element
                // in the trunk space (as a run's heat away from the contact): the linear
                // field is in both, so the bending is the same.
                let n = body.mesh.elements.len();
                let mixed: Vec<Space> = (0..n)
                    .map(|e| [Space::TensorProduct, Space::Trunk][e % 2])
                    .collect();
                for spaces in [vec![Space::TensorProduct; n], mixed] {
                    let u = solve_in(&body, |x| b * (x[1] - 4.0), &spaces);
                    let kappa = free * b;
                    let sag = kappa * 30.0 * 30.0 / 2.0;
                    for x in [7.5, 30.0, 41.0] {
                        let uz = body.values_at(&u, [x, 4.0]).unwrap().displacement[1];
                        let exact = kappa * x * (60.0 - x) / 2.0;
                        assert!(
                            (uz - exact).abs() < 1e-9 * sag,
                            "{analysis:?} p = {p} x = {x}: {uz} vs {exact}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn thermal_load_is_the_work_of_the_thermal_stress_on_curved_elements() {
        // For the discrete solution u of a thermal load, a(u, u) = ℓ(u): the strain energy
        // t∫ ε(u)·D ε(u) dA equals the work t∫ ε(u)·s ΔT dA of the thermal stress. Both are
        // integrated here at Gauss points, independently of the load's assembly and the
        // internal modes' recovery, for a temperature with every mode (edge modes of odd
        // degree on edges of either orientation, internal modes) on elements with an arc.
        // A wrong column or sign of the load would break the equality; round-off and the
        // rational maps' quadrature leave 1e-9.
        use crate::conduction::{ConductionBody, ConductionSpec};
        use crate::material::ThermalMaterial;
        use crate::quadrature::gauss_legendre;
        let p = 5;
        let block = MeshBlock {
            block: Block::new(
                [[0.0, 0.0], [40.0, 0.0], [40.0, 30.0], [0.0, 30.0]],
                [
                    EdgeShape::Straight,
                    EdgeShape::ArcAbout([-20.0, 15.0]),
                    EdgeShape::Straight,
                    EdgeShape::Straight,
                ],
            )
            .unwrap(),
            u_lines: vec![0.0, 0.4, 1.0],
            v_lines: vec![0.0, 0.5, 1.0],
            material: 0,
            edge_names: [None, None, None, None],
        };
        let mesh = Mesh::build(vec![block]).unwrap();
        for analysis in [
            Analysis::PlaneStress { thickness: 3.0 },
            Analysis::PlaneStrain { thickness: 3.0 },
        ] {
            let dofs = crate::dofs::DofMap::new(&mesh, p);
            let a = mesh.vertex_at([0.0, 0.0]).unwrap();
            let b = mesh.vertex_at([0.0, 30.0]).unwrap();
            let body = ElasticBody::new(
                "arc",
                mesh.clone(),
                vec![STEEL],
                analysis,
                Discretisation {
                    p,
                    space: Space::TensorProduct,
                },
                &Constraints {
                    fixed: vec![
                        dofs.vertex_dof(a, 0),
                        dofs.vertex_dof(a, 1),
                        dofs.vertex_dof(b, 0),
                    ],
                    ..Default::default()
                },
            )
            .unwrap();
            let heat = ConductionBody::new(
                &mesh,
                &ConductionSpec {
                    name: "arc".into(),
                    p,
                    space: Space::TensorProduct,
                    tensor_elements: vec![],
                    thickness: 3.0,
                    materials: vec![Some(ThermalMaterial::from_engineering(
                        50.0, 460.0, 7800.0, ALPHA,
                    ))],
                    edges: vec![],
                    faces: None,
                    flow: None,
                    inflow_temperature: 0.0,
                },
            )
            .unwrap();
            // A conforming field with every coefficient set (a fixed pseudo-random sequence).
            let mut seed = 12345u64;
            let field: Vec<f64> = (0..heat.n_full())
                .map(|_| {
                    seed = seed
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    ((seed >> 33) as f64 / (1u64 << 31) as f64) * 40.0 - 20.0
                })
                .collect();
            let rise = |e: usize| -> Vec<f64> {
                heat.element_unknowns(e)
                    .iter()
                    .map(|&(g, s)| s * field[g])
                    .collect()
            };
            let loads = body
                .thermal_loads(&[ALPHA], &vec![body.basis.space; body.mesh.elements.len()])
                .unwrap();
            let load = body.thermal_load_vector(&loads, rise);
            let mut rhs = faer::Mat::from_fn(load.len(), 1, |i, _| load[i]);
            body.solve_in_place(&mut rhs).unwrap();
            let u =
                body.recover_thermal((0..load.len()).map(|i| rhs[(i, 0)]).collect(), &loads, rise);
            let rule = gauss_legendre(p + 5);
            let (mut energy, mut work) = (0.0, 0.0);
            for element in 0..mesh.elements.len() {
                let coefficients = rise(element);
                for (i, &xi) in rule.points.iter().enumerate() {
                    for (j, &eta) in rule.points.iter().enumerate() {
                        let (_, det) = mesh.jacobian(element, xi, eta);
                        let w = rule.weights[i] * rule.weights[j] * det * 3.0;
                        let v = body.values_at_reference(&u, element, xi, eta);
                        let tab = body.basis.tabulate(&[xi], &[eta]);
                        let dt: f64 = coefficients
                            .iter()
                            .zip(&tab.values)
                            .map(|(c, n)| c * n)
                            .sum();
                        let s = body.thermal_stress(&loads, element, dt);
                        for ((e, sigma), th) in v.strain.iter().zip(&v.stress).zip(&s) {
                            energy += w * e * sigma;
                            work += w * e * th;
                        }
                    }
                }
            }
            assert!(energy > 0.0);
            assert!(
                (energy - work).abs() < 1e-9 * energy,
                "{analysis:?}: {energy} vs {work}"
            );
        }
    }
}
