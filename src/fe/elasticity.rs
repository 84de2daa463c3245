//! 2D linear elasticity with the p-version: element stiffness by tensor-product quadrature,
//! static condensation of the internal modes, entity-block assembly and one sparse Cholesky
//! factorisation, made on the first solve (or taken from the Schur complement's, which has
//! the contact trace ordered last) and kept for every later right-hand side.
//!
//! Element stiffness (strain vector ε = (ε_xx, ε_zz, γ_xz), σ = D ε, thickness t):
//! K_ab = t ∫ B_aᵀ D B_b dA. With G_x[a, q] = ∂N_a/∂x · √(w_q det J_q t) (and G_z likewise) the
//! four 2×2 blocks are K^xx = D₁₁ G_xG_xᵀ + D₃₃ G_zG_zᵀ, K^xz = D₁₂ G_xG_zᵀ + D₃₃ G_zG_xᵀ,
//! K^zz = D₂₂ G_zG_zᵀ + D₃₃ G_xG_xᵀ: three dense products per element.

use crate::basis::{QuadBasis, Space};
use crate::dofs::{DofMap, Pattern};
use crate::material::{Analysis, Material};
use crate::mesh::Mesh;
use crate::quadrature::gauss_legendre;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::linalg::solvers::Solve;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LltRef, SymbolicCholesky,
    SymmetricOrdering,
};
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{Conj, Mat, Par, Side};
use rayon::prelude::*;
use std::collections::HashMap;
use std::sync::OnceLock;

mod dissection;
mod schur;
mod supports;
mod thermal;
pub use schur::{Row, Trace};
pub use supports::Spring;
use supports::SpringBlock;
pub use thermal::ThermalLoads;

/// Errors of the elasticity stage.
#[derive(Debug, thiserror::Error)]
pub enum ElasticityError {
    /// The stiffness matrix is not positive definite: the body can move as a rigid body.
    #[error("the stiffness matrix of body \"{body}\" is singular: the supports do not prevent rigid-body motion")]
    Singular {
        /// Name of the body.
        body: String,
    },
    /// An internal-mode block failed to factorise (a degenerate element).
    #[error("element {element}: internal-mode stiffness is not positive definite")]
    Internal {
        /// Element index in the body's mesh.
        element: usize,
    },
}

/// Discretisation settings of one body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Discretisation {
    /// Polynomial degree p ≥ 1 of every element.
    pub p: usize,
    /// Tensor-product or trunk space.
    pub space: Space,
}

/// The supports of a body: held dofs (at zero or at a prescribed displacement) and elastic
/// supports (module `supports`: springs and prescribed displacements).
#[derive(Clone, Debug, Default)]
pub struct Constraints {
    /// Global dofs held (at zero unless `prescribed` gives a value).
    pub fixed: Vec<usize>,
    /// Held dofs with a non-zero displacement (global dof, mm); each also in `fixed`.
    pub prescribed: Vec<(usize, f64)>,
    /// Beds of springs along element edges.
    pub springs: Vec<Spring>,
}

/// An element type after condensation: all elements with equal geometry (up to translation),
/// material and quadrature share one.
struct CondensedElement {
    /// Condensed boundary stiffness S = K_bb − K_bi K_ii⁻¹ K_ib (N/mm), 8p × 8p.
    condensed: Mat<f64>,
    /// Recovery matrix R = K_ii⁻¹ K_ib: internal displacements are −R u_b.
    recovery: Mat<f64>,
}

/// Timing and size figures of the set-up.
#[derive(Clone, Debug, Default)]
pub struct SetupInfo {
    /// Unknowns before condensation (boundary + internal), including fixed ones.
    pub total_dofs: usize,
    /// Unknowns of the condensed global system.
    pub condensed_dofs: usize,
    /// Distinct element stiffness matrices actually computed.
    pub distinct_elements: usize,
    /// Non-zeros of the condensed matrix.
    pub nonzeros: usize,
}

/// One elastic body, assembled, condensed and factorised: ready for any number of load cases.
pub struct ElasticBody {
    /// Body name (for messages).
    pub name: String,
    /// The mesh.
    pub mesh: Mesh,
    /// Materials indexed by the elements' `material`.
    pub materials: Vec<Material>,
    /// Plane stress or plane strain, with the thickness.
    pub analysis: Analysis,
    /// The shape functions.
    pub basis: QuadBasis,
    /// Global numbering of the boundary dofs.
    pub dofs: DofMap,
    element_type: Vec<usize>,
    types: Vec<CondensedElement>,
    fixed: Vec<bool>,
    /// The prescribed displacement of every held dof (0 elsewhere and at dofs held at 0), mm.
    prescribed: Vec<f64>,
    /// −K_fp u_p: what the prescribed displacements load the free dofs with, N (empty if
    /// there are none).
    lift: Vec<f64>,
    /// The elastic supports.
    springs: Vec<Spring>,
    /// The Cholesky factorisation of `matrix`, made on first use.
    factor: OnceLock<Factor>,
    /// The condensed stiffness matrix (N/mm), fixed rows and columns replaced by the identity;
    /// its lower triangle only.
    matrix: SparseColMat<usize, f64>,
    /// Size figures of the set-up.
    pub info: SetupInfo,
}

/// A sparse Cholesky factorisation L Lᵀ = P K Pᵀ in the ordering P it was made with.
#[derive(Debug)]
struct Factor {
    symbolic: SymbolicCholesky<usize>,
    values: Vec<f64>,
}

impl Factor {
    /// Factorise `matrix` (lower triangle) in `ordering`; None if it is not positive definite.
    fn new(
        matrix: &SparseColMat<usize, f64>,
        ordering: SymmetricOrdering<'_, usize>,
        params: CholeskySymbolicParams<'_>,
    ) -> Option<Factor> {
        let symbolic =
            factorize_symbolic_cholesky(matrix.symbolic(), Side::Lower, ordering, params).ok()?;
        let mut values = large_zeroed(symbolic.len_val());
        let mut buffer = MemBuffer::new(
            symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
        );
        symbolic
            .factorize_numeric_llt(
                &mut values,
                matrix.as_ref(),
                Side::Lower,
                LltRegularization::default(),
                Par::Seq,
                MemStack::new(&mut buffer),
                Default::default(),
            )
            .ok()?;
        Some(Factor { symbolic, values })
    }
}

/// A vector of `len` zeros whose memory the kernel may back with 2 MB pages when it is
/// large. The factor of a body at 513 contact points has 5 million entries: 40 MB, ten
/// thousand 4 kB page faults on first touch, each a few µs on this virtual machine; with 2 MB
/// pages twenty. Below [`HUGE_PAGES_FROM`] bytes the advice costs more than it saves (each
/// 2 MB page is zeroed whole): punch-b40's 2.4 MB factor, made afresh in every run of a
/// benchmark, took 3 ms longer per 1700-step run with it.
fn large_zeroed(len: usize) -> Vec<f64> {
    let mut v = Vec::<f64>::with_capacity(len);
    let bytes = len * std::mem::size_of::<f64>();
    #[cfg(target_os = "linux")]
    if bytes >= HUGE_PAGES_FROM {
        advise_huge_pages(v.as_mut_ptr() as usize, bytes);
    }
    v.resize(len, 0.0);
    v
}

/// Size in bytes from which [`large_zeroed`] asks for huge pages.
const HUGE_PAGES_FROM: usize = 16 << 20;

/// Ask for transparent huge pages on the 2 MB-aligned part of `bytes` bytes at `start`
/// (not yet touched). Only advice: it changes no contents, and a kernel that ignores it
/// (THP off) or fails it leaves 4 kB pages.
#[cfg(target_os = "linux")]
fn advise_huge_pages(start: usize, bytes: usize) {
    const HUGE: usize = 2 << 20;
    let (first, end) = (start.next_multiple_of(HUGE), (start + bytes) / HUGE * HUGE);
    if end > first {
        // SAFETY: the range lies inside one live allocation of ours, and MADV_HUGEPAGE
        // neither unmaps it nor changes what it holds.
        unsafe {
            libc::madvise(first as *mut libc::c_void, end - first, libc::MADV_HUGEPAGE);
        }
    }
}

/// The displacement field of a body: global boundary dofs plus recovered internal modes.
#[derive(Clone, Debug)]
pub struct Displacement {
    /// Global boundary dofs (mm).
    pub boundary: Vec<f64>,
    /// Per element, all local mode coefficients (mode-major, 2a + c), mm.
    pub local: Vec<Vec<f64>>,
}

pub(crate) fn quadrature_points(mesh: &Mesh, element: usize, p: usize) -> usize {
    // Parallelogram maps make the integrand polynomial of degree 2p per direction: p + 1
    // Gauss points are exact. Other maps are rational or transcendental: p + 3 points keep the
    // quadrature error below the discretisation error for the meshes we ship (checked by the
    // patch and Lamé tests).
    let (j0, _) = mesh.jacobian(element, -1.0, -1.0);
    let affine = [(1.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (0.0, 0.0)]
        .iter()
        .all(|&(x, y)| {
            let (j, _) = mesh.jacobian(element, x, y);
            let scale = j0.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
            j.iter()
                .flatten()
                .zip(j0.iter().flatten())
                .all(|(a, b)| (a - b).abs() <= 1e-12 * scale)
        });
    if affine {
        p + 1
    } else {
        p + 3
    }
}

/// A key that is equal for elements whose maps agree up to a translation.
pub(crate) fn geometry_key(mesh: &Mesh, element: usize, material: usize, nq: usize) -> Vec<i64> {
    let origin = mesh.map(element, -1.0, -1.0);
    let far = mesh.map(element, 1.0, 1.0);
    let size = (far[0] - origin[0]).hypot(far[1] - origin[1]).max(1e-300);
    let mut key = vec![material as i64, nq as i64];
    for i in 0..5 {
        for j in 0..5 {
            let x = mesh.map(element, -1.0 + 0.5 * i as f64, -1.0 + 0.5 * j as f64);
            for d in 0..2 {
                key.push(((x[d] - origin[d]) / size * 1e10).round() as i64);
            }
            key.push((size * 1e6).round() as i64);
        }
    }
    key
}

pub(crate) fn element_stiffness(
    mesh: &Mesh,
    element: usize,
    basis: &QuadBasis,
    material: &Material,
    analysis: Analysis,
    nq: usize,
) -> Mat<f64> {
    let rule = gauss_legendre(nq);
    let tab = basis.tabulate(&rule.points, &rule.points);
    let n = basis.n_modes();
    let n_points = nq * nq;
    let mut gx = Mat::<f64>::zeros(n, n_points);
    let mut gz = Mat::<f64>::zeros(n, n_points);
    // Axisymmetric: the hoop strain's row, H[a, q] = N_a/r · √(w_q det J_q 2πr).
    let axisymmetric = analysis.is_axisymmetric();
    let mut hoop = Mat::<f64>::zeros(if axisymmetric { n } else { 0 }, n_points);
    for iy in 0..nq {
        for ix in 0..nq {
            let q = iy * nq + ix;
            let (xi, eta) = (rule.points[ix], rule.points[iy]);
            let (j, det) = mesh.jacobian(element, xi, eta);
            // The point itself only where the weight (2πr) or the hoop strain needs it.
            let x = if axisymmetric {
                mesh.map(element, xi, eta)
            } else {
                [0.0; 2]
            };
            let scale = (rule.weights[ix] * rule.weights[iy] * det * analysis.weight(x)).sqrt();
            // Rows of J⁻¹: ∂ξ/∂(x, z) and ∂η/∂(x, z).
            let (dxi_dx, dxi_dz) = (j[1][1] / det, -j[0][1] / det);
            let (deta_dx, deta_dz) = (-j[1][0] / det, j[0][0] / det);
            for a in 0..n {
                let (nxi, neta) = (tab.d_xi[a * n_points + q], tab.d_eta[a * n_points + q]);
                gx[(a, q)] = (nxi * dxi_dx + neta * deta_dx) * scale;
                gz[(a, q)] = (nxi * dxi_dz + neta * deta_dz) * scale;
                if axisymmetric {
                    // Gauss points lie inside the element, never on the axis (r > 0).
                    hoop[(a, q)] = tab.values[a * n_points + q] / x[0] * scale;
                }
            }
        }
    }
    let xx = &gx * gx.transpose();
    let zz = &gz * gz.transpose();
    let xz = &gx * gz.transpose();
    let d = material.constitutive(analysis);
    let mut k = Mat::from_fn(2 * n, 2 * n, |r, c| {
        let (a, ca, b, cb) = (r / 2, r % 2, c / 2, c % 2);
        match (ca, cb) {
            (0, 0) => d[0][0] * xx[(a, b)] + d[2][2] * zz[(a, b)],
            (1, 1) => d[1][1] * zz[(a, b)] + d[2][2] * xx[(a, b)],
            (0, 1) => d[0][1] * xz[(a, b)] + d[2][2] * xz[(b, a)],
            _ => d[1][0] * xz[(b, a)] + d[2][2] * xz[(a, b)],
        }
    });
    if axisymmetric {
        // ε_θθ = u_r/r couples to ε_rr and ε_zz by λ and to itself by λ + 2μ.
        let (lambda, hoop_modulus) = material.hoop_coupling();
        let hh = &hoop * hoop.transpose();
        let xh = &gx * hoop.transpose();
        let zh = &gz * hoop.transpose();
        for a in 0..n {
            for b in 0..n {
                k[(2 * a, 2 * b)] += hoop_modulus * hh[(a, b)] + lambda * (xh[(a, b)] + xh[(b, a)]);
                k[(2 * a, 2 * b + 1)] += lambda * zh[(b, a)];
                k[(2 * a + 1, 2 * b)] += lambda * zh[(a, b)];
            }
        }
    }
    k
}

fn condense(k: &Mat<f64>, nb: usize, element: usize) -> Result<CondensedElement, ElasticityError> {
    let n = k.nrows();
    let ni = n - nb;
    if ni == 0 {
        return Ok(CondensedElement {
            condensed: k.clone(),
            recovery: Mat::zeros(0, nb),
        });
    }
    let kii = k.submatrix(nb, nb, ni, ni);
    let kib = k.submatrix(nb, 0, ni, nb);
    let llt = kii
        .llt(Side::Lower)
        .map_err(|_| ElasticityError::Internal { element })?;
    let recovery = llt.solve(kib);
    let condensed = k.submatrix(0, 0, nb, nb) - kib.transpose() * &recovery;
    Ok(CondensedElement {
        condensed,
        recovery,
    })
}

impl ElasticBody {
    /// Assemble, condense and factorise one body.
    pub fn new(
        name: &str,
        mesh: Mesh,
        materials: Vec<Material>,
        analysis: Analysis,
        discretisation: Discretisation,
        constraints: &Constraints,
    ) -> Result<ElasticBody, ElasticityError> {
        let basis = QuadBasis::new(discretisation.p, discretisation.space);
        let dofs = DofMap::new(&mesh, discretisation.p);
        let nb = 2 * basis.n_boundary();
        let mut cache: HashMap<Vec<i64>, usize> = HashMap::new();
        // The first element of each distinct type, with its quadrature.
        let mut distinct: Vec<(usize, usize)> = Vec::new();
        let mut element_type = Vec::with_capacity(mesh.elements.len());
        for element in 0..mesh.elements.len() {
            let material = mesh.elements[element].material;
            let nq = quadrature_points(&mesh, element, discretisation.p);
            let mut key = geometry_key(&mesh, element, material, nq);
            if analysis.is_axisymmetric() {
                // Elements alike up to a translation along the axis only: the radius enters.
                key.push(mesh.map(element, -1.0, -1.0)[0].to_bits() as i64);
            }
            let id = *cache.entry(key).or_insert_with(|| {
                distinct.push((element, nq));
                distinct.len() - 1
            });
            element_type.push(id);
        }
        // Each distinct element is computed on its own, in parallel: a body of revolution has
        // one per radius (no translation in r leaves its stiffness alone), 234 in
        // `ball-on-flat` against a handful in a plane example.
        let types = distinct
            .par_iter()
            .map(|&(element, nq)| {
                let material = &materials[mesh.elements[element].material];
                let k = element_stiffness(&mesh, element, &basis, material, analysis, nq);
                condense(&k, nb, element)
            })
            .collect::<Result<Vec<CondensedElement>, ElasticityError>>()?;
        let n = dofs.n_dofs();
        let mut fixed = vec![false; n];
        for &d in &constraints.fixed {
            fixed[d] = true;
        }
        let mut prescribed = vec![0.0; n];
        for &(d, value) in &constraints.prescribed {
            fixed[d] = true;
            prescribed[d] = value;
        }
        let held = if analysis.is_axisymmetric() {
            // A body of revolution has one rigid motion, along its axis: a radial
            // translation or a turn would strain its hoops.
            holds_axial_motion(&dofs, &fixed, &constraints.springs, &mesh)
        } else {
            prevents_rigid_motion(&mesh, &dofs, &fixed, &constraints.springs)
        };
        if !held {
            // The factorisation alone would not catch it: on curved elements round-off leaves
            // the rigid-body pivots tiny but positive, and the solve returns nonsense.
            return Err(ElasticityError::Singular {
                body: name.to_string(),
            });
        }
        let pattern = Pattern::new(&mesh, &dofs);
        let springs: Vec<SpringBlock> = constraints
            .springs
            .iter()
            .map(|s| SpringBlock::new(&mesh, &dofs, &basis, analysis, s))
            .collect();
        let mut values = assemble(&mesh, &dofs, &pattern, &element_type, &types);
        for spring in &springs {
            spring.add_to(&pattern, &mut values);
        }
        hold(&pattern, &fixed, &mut values);
        let lift = if constraints.prescribed.is_empty() {
            Vec::new()
        } else {
            let mut lift = vec![0.0; n];
            add_element_forces(
                &mesh,
                &dofs,
                &element_type,
                &types,
                &prescribed,
                -1.0,
                &mut lift,
            );
            for spring in &springs {
                spring.add_forces(&prescribed, -1.0, &mut lift);
            }
            lift
        };
        let info = SetupInfo {
            total_dofs: n + mesh.elements.len() * 2 * basis.n_internal(),
            condensed_dofs: n,
            distinct_elements: types.len(),
            // Both triangles, as before only the lower one was stored.
            nonzeros: 2 * values.len() - n,
        };
        let symbolic =
            SymbolicSparseColMat::new_checked(n, n, pattern.col_ptr, None, pattern.row_idx);
        let matrix = SparseColMat::new(symbolic, values);
        Ok(ElasticBody {
            name: name.to_string(),
            mesh,
            materials,
            analysis,
            basis,
            dofs,
            element_type,
            types,
            fixed,
            prescribed,
            lift,
            springs: constraints.springs.clone(),
            factor: OnceLock::new(),
            matrix,
            info,
        })
    }

    /// The factorisation of the condensed stiffness, made now if no earlier step made it.
    fn factor(&self) -> Result<&Factor, ElasticityError> {
        if let Some(factor) = self.factor.get() {
            return Ok(factor);
        }
        let factor = Factor::new(&self.matrix, SymmetricOrdering::Amd, Default::default())
            .ok_or_else(|| ElasticityError::Singular {
                body: self.name.clone(),
            })?;
        Ok(self.factor.get_or_init(|| factor))
    }

    /// Keep `factor` (of this body's matrix, in any ordering) for later solves, unless one is
    /// kept already.
    fn keep_factor(&self, factor: Factor) {
        let _ = self.factor.set(factor);
    }

    /// Solve K u = f in place for every column of `rhs` (global boundary dofs, N → mm).
    /// Entries of `rhs` at fixed dofs are ignored (set to zero). Fails only if the stiffness
    /// is not positive definite (found by the first solve's factorisation).
    pub fn solve_in_place(&self, rhs: &mut Mat<f64>) -> Result<(), ElasticityError> {
        for (d, &f) in self.fixed.iter().enumerate() {
            if f {
                for c in 0..rhs.ncols() {
                    rhs[(d, c)] = 0.0;
                }
            }
        }
        let factor = self.factor()?;
        let mut buffer = MemBuffer::new(
            factor
                .symbolic
                .solve_in_place_scratch::<f64>(rhs.ncols(), Par::Seq),
        );
        LltRef::new(&factor.symbolic, &factor.values).solve_in_place_with_conj(
            Conj::No,
            rhs.as_mut(),
            Par::Seq,
            MemStack::new(&mut buffer),
        );
        Ok(())
    }

    /// Displacement field for the global load vector `load` (N, one entry per global dof),
    /// with the prescribed displacements of the supports.
    pub fn solve(&self, load: &[f64]) -> Result<Displacement, ElasticityError> {
        let boundary = self.solve_boundary(load)?;
        Ok(self.recover(boundary))
    }

    /// The boundary dofs' displacement (mm) under `load` (N) and the prescribed displacements:
    /// the lift added to the load, the solve, and the held dofs set to their values.
    pub fn solve_boundary(&self, load: &[f64]) -> Result<Vec<f64>, ElasticityError> {
        let mut rhs = Mat::from_fn(load.len(), 1, |i, _| {
            load[i] + self.lift.get(i).copied().unwrap_or(0.0)
        });
        self.solve_in_place(&mut rhs)?;
        Ok((0..load.len())
            .map(|i| {
                if self.fixed[i] {
                    self.prescribed[i]
                } else {
                    rhs[(i, 0)]
                }
            })
            .collect())
    }

    /// Whether some support prescribes a non-zero displacement: then the body moves even
    /// without loads.
    pub fn has_prescribed(&self) -> bool {
        !self.lift.is_empty()
    }

    /// The energy stored in the body and its elastic supports at `u` (N·mm):
    /// ½ Σ_e u_eᵀ S_e u_e over the condensed element matrices, plus the springs'. It is
    /// ½ fᵀu when every held dof is at zero, and counts the supports' work when not.
    pub fn stored_energy(&self, u: &Displacement) -> f64 {
        let mut forces = vec![0.0; u.boundary.len()];
        add_element_forces(
            &self.mesh,
            &self.dofs,
            &self.element_type,
            &self.types,
            &u.boundary,
            1.0,
            &mut forces,
        );
        let elastic: f64 = 0.5
            * forces
                .iter()
                .zip(&u.boundary)
                .map(|(f, v)| f * v)
                .sum::<f64>();
        elastic
            + self
                .springs
                .iter()
                .map(|s| SpringBlock::new(&self.mesh, &self.dofs, &self.basis, self.analysis, s))
                .map(|block| block.energy(&u.boundary))
                .sum::<f64>()
    }

    /// Recover the internal modes of every element from the boundary dofs.
    pub fn recover(&self, boundary: Vec<f64>) -> Displacement {
        let nb = 2 * self.basis.n_boundary();
        let local = (0..self.mesh.elements.len())
            .map(|e| {
                let ed = self.dofs.element_dofs(&self.mesh, e);
                let mut u: Vec<f64> = ed
                    .global
                    .iter()
                    .zip(&ed.sign)
                    .map(|(&g, &s)| s * boundary[g])
                    .collect();
                let r = &self.types[self.element_type[e]].recovery;
                for i in 0..r.nrows() {
                    let mut acc = 0.0;
                    for b in 0..nb {
                        acc -= r[(i, b)] * u[b];
                    }
                    u.push(acc);
                }
                u
            })
            .collect();
        Displacement { boundary, local }
    }

    /// Whether global dof `d` is held by a support.
    pub fn is_fixed(&self, d: usize) -> bool {
        self.fixed[d]
    }
}

/// Whether the fixed vertex dofs rule out every plane rigid-body motion (two translations and
/// a rotation). Each fixed component at a vertex (x, z) is a row of the constraint matrix on
/// (t_x, t_z, θ): [1, 0, −z] or [0, 1, x], in coordinates centred and scaled by the mesh; the
/// motion is prevented when the 3 × 3 Gram matrix of the rows is far from singular.
fn prevents_rigid_motion(mesh: &Mesh, dofs: &DofMap, fixed: &[bool], springs: &[Spring]) -> bool {
    let count = mesh.vertices.len().max(1) as f64;
    let centre = mesh.vertices.iter().fold([0.0, 0.0], |c, v| {
        [c[0] + v[0] / count, c[1] + v[1] / count]
    });
    let size = mesh
        .vertices
        .iter()
        .map(|v| (v[0] - centre[0]).hypot(v[1] - centre[1]))
        .fold(0.0f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut gram = [[0.0f64; 3]; 3];
    for (v, x) in mesh.vertices.iter().enumerate() {
        let (dx, dz) = ((x[0] - centre[0]) / size, (x[1] - centre[1]) / size);
        let rows = [[1.0, 0.0, -dz], [0.0, 1.0, dx]];
        for (c, row) in rows.iter().enumerate() {
            if fixed[dofs.vertex_dof(v, c)] {
                for a in 0..3 {
                    for b in 0..3 {
                        gram[a][b] += row[a] * row[b];
                    }
                }
            }
        }
    }
    // A spring bed holds the motion along its normal (and its tangent) at the points of its
    // edge: the rows n·(translation + rotation) there, as for a held component.
    for spring in springs {
        for t in [-1.0, 0.0, 1.0] {
            let x = mesh.point_on_edge(spring.element, spring.local, t);
            let (dx, dz) = ((x[0] - centre[0]) / size, (x[1] - centre[1]) / size);
            let (_, n) = mesh.edge_frame(spring.element, spring.local, t);
            let tangent = [-n[1], n[0]];
            for (k, d) in [(spring.normal, n), (spring.tangential, tangent)] {
                if k > 0.0 {
                    let row = [d[0], d[1], -dz * d[0] + dx * d[1]];
                    for a in 0..3 {
                        for b in 0..3 {
                            gram[a][b] += row[a] * row[b];
                        }
                    }
                }
            }
        }
    }
    let det = gram[0][0] * (gram[1][1] * gram[2][2] - gram[1][2] * gram[2][1])
        - gram[0][1] * (gram[1][0] * gram[2][2] - gram[1][2] * gram[2][0])
        + gram[0][2] * (gram[1][0] * gram[2][1] - gram[1][1] * gram[2][0]);
    let trace = gram[0][0] + gram[1][1] + gram[2][2];
    // det/trace³ is scale-free and bounded by 1/27; 1e-12 only rejects true rank loss.
    trace > 0.0 && det / trace.powi(3) > 1e-12
}

/// Whether a held z dof or a spring bed with a z component holds a body of revolution's one
/// rigid motion, its translation along the axis.
fn holds_axial_motion(dofs: &DofMap, fixed: &[bool], springs: &[Spring], mesh: &Mesh) -> bool {
    let held = (0..mesh.vertices.len()).any(|v| fixed[dofs.vertex_dof(v, 1)]);
    held || springs.iter().any(|s| {
        [-1.0, 0.0, 1.0].iter().any(|&t| {
            let (_, n) = mesh.edge_frame(s.element, s.local, t);
            (s.normal > 0.0 && n[1].abs() > 1e-9) || (s.tangential > 0.0 && n[0].abs() > 1e-9)
        })
    })
}

/// Add every element's condensed stiffness into the pattern's value array, block by block.
fn assemble(
    mesh: &Mesh,
    dofs: &DofMap,
    pattern: &Pattern,
    element_type: &[usize],
    types: &[CondensedElement],
) -> Vec<f64> {
    let mut values = vec![0.0; pattern.row_idx.len()];
    let p = dofs.p;
    // Local boundary dofs of each of the 8 entities: vertex k → 2 dofs at 2k; edge e → 2(p−1)
    // dofs starting after the 8 vertex dofs.
    let entity_local: Vec<std::ops::Range<usize>> = (0..8)
        .map(|k| {
            if k < 4 {
                2 * k..2 * k + 2
            } else {
                8 + 2 * (p - 1) * (k - 4)..8 + 2 * (p - 1) * (k - 3)
            }
        })
        .collect();
    for (element, &ty) in element_type.iter().enumerate() {
        let ed = dofs.element_dofs(mesh, element);
        let s = &types[ty].condensed;
        for (cb, col_range) in entity_local.iter().enumerate() {
            for (rb, row_range) in entity_local.iter().enumerate() {
                if ed.entities[rb] < ed.entities[cb] {
                    continue;
                }
                for lc in col_range.clone() {
                    let gc = ed.global[lc];
                    let (start, first) = pattern.block_start(gc, ed.entities[cb], ed.entities[rb]);
                    let rows = row_range.clone().skip(first);
                    for (value, lr) in values[start..].iter_mut().zip(rows) {
                        *value += ed.sign[lr] * ed.sign[lc] * s[(lr, lc)];
                    }
                }
            }
        }
    }
    values
}

/// The elements' forces S_e u_e at global displacement `u` (N), assembled into `out` times
/// `scale`: the stiffness applied element by element, without the held rows' identity.
fn add_element_forces(
    mesh: &Mesh,
    dofs: &DofMap,
    element_type: &[usize],
    types: &[CondensedElement],
    u: &[f64],
    scale: f64,
    out: &mut [f64],
) {
    for (element, &ty) in element_type.iter().enumerate() {
        let ed = dofs.element_dofs(mesh, element);
        let local: Vec<f64> = ed
            .global
            .iter()
            .zip(&ed.sign)
            .map(|(&g, &s)| s * u[g])
            .collect();
        if local.iter().all(|&v| v == 0.0) {
            continue;
        }
        let k = &types[ty].condensed;
        for (a, (&g, &s)) in ed.global.iter().zip(&ed.sign).enumerate() {
            out[g] += scale * s * (0..local.len()).map(|b| k[(a, b)] * local[b]).sum::<f64>();
        }
    }
}

/// Replace the held dofs' rows and columns of the assembled values by the identity.
fn hold(pattern: &Pattern, fixed: &[bool], values: &mut [f64]) {
    for col in 0..fixed.len() {
        let range = pattern.col_ptr[col]..pattern.col_ptr[col + 1];
        for (value, &row) in values[range.clone()]
            .iter_mut()
            .zip(&pattern.row_idx[range])
        {
            if fixed[col] || fixed[row] {
                *value = if row == col { 1.0 } else { 0.0 };
            }
        }
    }
}
