//! Heat conduction by the same p-version elements as the elasticity: the same mesh, exact
//! geometry and hierarchical basis, with one unknown per mode (the temperature). This module
//! builds the operators of one body; the time integration is in [`reduced`] (the run's
//! exact-in-time reduced model) and [`transient`] (a full-order reference for checks).
//!
//! # The equations
//!
//! A plane body of thickness t (mm) with conductivity k (mW/(mm·K)), heat capacity ρc
//! (mJ/(mm³·K)) and, for a thin plate in plane stress, faces losing heat to T∞ with a film
//! coefficient h_f (mW/(mm²·K)) on both sides:
//!
//! ρc ∂T/∂t = ∇·(k ∇T) − (2 h_f / t)(T − T∞)
//!
//! with, on each edge, a held temperature, convection −k ∂T/∂n = h (T − T∞), a given inward
//! flux q (mW/mm²; the frictional heat of the contact) or nothing (insulated). Multiplying by
//! a shape function N_a and integrating over the body's volume gives C Ṫ + K T = f with
//!
//! - C_ab = t ∫ ρc N_a N_b dA (capacity, mJ/K),
//! - K_ab = t ∫ k ∇N_a·∇N_b dA + 2 h_f ∫ N_a N_b dA + t Σ_edges ∫ h N_a N_b ds (mW/K),
//! - f_a = 2 h_f T∞ ∫ N_a dA + t Σ_edges ∫ h T∞ N_a ds + t ∫ q N_a ds (mW).
//!
//! Units: mm, s, mJ (= N·mm), mW, °C for temperatures (K for differences). The element
//! integrals use the elasticity's Gauss rules (exact on parallelograms, p + 3 points on curved
//! elements), so a temperature that the basis contains is reproduced to round-off.
//!
//! # Unknowns
//!
//! Unlike the elasticity, the internal modes are kept: the capacity couples them in time, so
//! static condensation would not be exact. The *full* numbering is the scalar boundary dofs
//! ([`DofMap::scalar`]) followed by each element's internal modes, as many as its space has
//! ([`spaces`]: the tensor-product space along the contact, the trunk space elsewhere by
//! default). A held temperature is a
//! constant along its edge: its vertex dofs take the value, its edge modes zero; held dofs
//! are eliminated, and the matrices are over the *free* dofs only (positive definite unless
//! no edge holds or convects and no face convects: then K has the constants in its kernel).

use crate::basis::Space;
use crate::dofs::DofMap;
use crate::geometry::Point;
use crate::material::ThermalMaterial;
use crate::mesh::Mesh;
use faer::sparse::SparseColMat;
use std::collections::HashMap;
use std::sync::{Arc, OnceLock};

pub mod advection;
mod balance;
pub mod blocks;
pub mod closed_forms;
mod element;
mod krylov;
pub mod reduced;
pub mod spaces;
pub mod transient;
pub use advection::Flow;
pub use balance::HeatFlows;
use blocks::{assemble_pair, Block, BlockOperator, PairedMatrices};
pub use element::piece_quadrature;
use element::{convection_block, element_matrices, ElementMatrices};
pub use spaces::ElementSpaces;

/// Errors of the conduction stage.
#[derive(Debug, thiserror::Error)]
pub enum ConductionError {
    /// A material of an element has no thermal properties (or non-positive ones).
    #[error("material {material} of an element of body \"{body}\" has no valid thermal properties (conductivity and heat capacity must be positive)")]
    Material {
        /// Body name.
        body: String,
        /// Material index.
        material: usize,
    },
    /// A held temperature on part of an element edge: the edge's modes cannot hold a value
    /// on part of it and leave the rest free.
    #[error("body \"{body}\": a temperature is held on part of an element edge (element {element}, edge parameters {from} … {to}); the whole element edge would be held, also where it is not asked")]
    PartialHeld {
        /// Body name.
        body: String,
        /// Element index.
        element: usize,
        /// Where the piece starts along the edge (−1 … 1).
        from: f64,
        /// Where it ends.
        to: f64,
    },
    /// The sparse matrices could not be built or factorised.
    #[error("body \"{body}\": {message}")]
    Numerical {
        /// Body name.
        body: String,
        /// What failed.
        message: String,
    },
}

/// What happens on a piece of boundary.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EdgeCondition {
    /// Temperature held at this value, °C.
    Temperature(f64),
    /// Convection −k ∂T/∂n = h (T − T∞): `coefficient` h in mW/(mm²·K), `ambient` T∞ in °C.
    Convection {
        /// Film coefficient h, mW/(mm²·K).
        coefficient: f64,
        /// Ambient temperature T∞, °C.
        ambient: f64,
    },
}

/// A part of one element edge: local edge `local` of `element`, between edge parameters
/// `t[0] < t[1]` in [−1, 1] (the whole edge is [−1, 1]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgePiece {
    /// Element index.
    pub element: usize,
    /// Local edge 0..4.
    pub local: usize,
    /// Parameter interval along the edge.
    pub t: [f64; 2],
}

impl EdgePiece {
    /// The whole local edge `local` of `element`.
    pub fn whole(element: usize, local: usize) -> EdgePiece {
        EdgePiece {
            element,
            local,
            t: [-1.0, 1.0],
        }
    }

    /// Every element edge of the mesh's edge named `name`, whole (none if there is no such
    /// name).
    pub fn named(mesh: &Mesh, name: &str) -> Vec<EdgePiece> {
        mesh.named_edges
            .get(name)
            .map(|edges| edges.iter().map(|&(e, l)| EdgePiece::whole(e, l)).collect())
            .unwrap_or_default()
    }
}

/// Convection from both faces of a plane-stress plate: a sink 2h/t (T − T∞) per unit volume.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceConvection {
    /// Film coefficient h of each face, mW/(mm²·K).
    pub coefficient: f64,
    /// Ambient temperature T∞, °C.
    pub ambient: f64,
}

/// The thermal description of one body, as the conduction stage needs it.
#[derive(Clone, Debug)]
pub struct ConductionSpec {
    /// Body name (for messages).
    pub name: String,
    /// Degree and space of the elements.
    pub p: usize,
    /// The elements' space: tensor-product or trunk.
    pub space: Space,
    /// Elements in the tensor-product space whatever `space` is: where the heat enters in a
    /// thin layer ([`spaces`]).
    pub tensor_elements: Vec<usize>,
    /// Thickness t, mm.
    pub thickness: f64,
    /// Thermal properties indexed by the elements' `material`; None for a material without.
    pub materials: Vec<Option<ThermalMaterial>>,
    /// Edge conditions (every other edge is insulated).
    pub edges: Vec<(EdgePiece, EdgeCondition)>,
    /// Convection from the faces (plane stress only).
    pub faces: Option<FaceConvection>,
    /// The material's motion through the frame of the heat problem (None: at rest).
    pub flow: Option<Flow>,
    /// The temperature of the material entering where it flows in, °C (with `flow`).
    pub inflow_temperature: f64,
}

/// One body's heat conduction operators over its free dofs.
#[derive(Clone, Debug)]
pub struct ConductionBody {
    /// Body name.
    pub name: String,
    /// The mesh.
    pub mesh: Mesh,
    /// Each element's space and shape functions.
    pub spaces: ElementSpaces,
    /// Scalar numbering of the boundary dofs.
    pub dofs: DofMap,
    /// Thickness t, mm.
    pub thickness: f64,
    /// Free index of each full unknown (`usize::MAX` where the temperature is held).
    free_of: Vec<usize>,
    /// Value of each full unknown where held (°C for vertex dofs, 0 for edge modes).
    held: Vec<Option<f64>>,
    /// K (mW/K) over the full unknowns as blocks: the elements' and the convecting edges'.
    conductivity_blocks: Vec<Block>,
    /// C (mJ/K) over the full unknowns as the elements' blocks.
    capacity_blocks: Vec<Block>,
    /// The constant sources over the free dofs (mW): ambient terms, minus K times the held
    /// temperatures.
    pub load: Vec<f64>,
    /// The constant sources over the full unknowns, for the heat flowing in where
    /// temperatures are held.
    full_load: Vec<f64>,
    /// K and C over the free unknowns, assembled on first use.
    free_matrices: OnceLock<PairedMatrices>,
    /// Edge pieces and faces with their conditions, for the heat they pass.
    edges: Vec<(EdgePiece, EdgeCondition)>,
    faces: Option<FaceConvection>,
    /// Whether some edge holds or convects or the faces convect: heat can leave.
    pub has_exit: bool,
    n_free: usize,
    /// The advection and inflow blocks (also in the conductivity), for the heat the motion
    /// carries out.
    advection_blocks: Vec<Block>,
    /// The enthalpy the entering material brings at the inflow temperature, mW.
    inflow_enthalpy: f64,
}

/// y += A x for a sparse matrix stored in full (both triangles).
pub fn add_product(a: &SparseColMat<usize, f64>, x: &[f64], y: &mut [f64]) {
    let col_ptr = a.symbolic().col_ptr();
    let row_idx = a.symbolic().row_idx();
    let values = a.val();
    for (j, &xj) in x.iter().enumerate() {
        if xj == 0.0 {
            continue;
        }
        let range = col_ptr[j]..col_ptr[j + 1];
        for (&i, &v) in row_idx[range.clone()].iter().zip(&values[range]) {
            y[i] += v * xj;
        }
    }
}

impl ConductionBody {
    /// Build the operators of one body on `mesh`.
    pub fn new(mesh: &Mesh, spec: &ConductionSpec) -> Result<ConductionBody, ConductionError> {
        let dofs = DofMap::scalar(mesh, spec.p);
        let spaces = ElementSpaces::new(mesh, &dofs, spec.p, spec.space, &spec.tensor_elements);
        let n_full = spaces.n_full();
        let face = spec.faces.map_or(0.0, |f| f.coefficient);
        let mut conductivity_blocks = Vec::with_capacity(mesh.elements.len());
        let mut capacity_blocks = Vec::with_capacity(mesh.elements.len());
        let mut load = vec![0.0; n_full];
        let mut cache: HashMap<(Vec<i64>, Space), ElementMatrices> = HashMap::new();
        for element in 0..mesh.elements.len() {
            let m = mesh.elements[element].material;
            let material = spec.materials.get(m).copied().flatten().filter(|t| {
                t.conductivity > 0.0 && t.heat_capacity > 0.0 && t.conductivity.is_finite()
            });
            let Some(material) = material else {
                return Err(ConductionError::Material {
                    body: spec.name.clone(),
                    material: m,
                });
            };
            let nq = crate::elasticity::quadrature_points(mesh, element, spec.p);
            let basis = spaces.basis(element);
            let key = (
                crate::elasticity::geometry_key(mesh, element, m, nq),
                basis.space,
            );
            let matrices = cache.entry(key).or_insert_with(|| {
                element_matrices(mesh, element, basis, &material, spec.thickness, face, nq)
            });
            let unknowns = spaces.unknowns(mesh, &dofs, element);
            if let Some(f) = spec.faces {
                for (a, &(ga, sa)) in unknowns.iter().enumerate() {
                    // The face sink's ambient part: 2 h_f T∞ ∫ N_a dA = 2 h_f T∞ (t ∫N_a dA)/t.
                    load[ga] +=
                        sa * 2.0 * f.coefficient * f.ambient * matrices.volume[a] / spec.thickness;
                }
            }
            conductivity_blocks.push(Block {
                unknowns: unknowns.clone(),
                matrix: Arc::clone(&matrices.conductivity),
            });
            capacity_blocks.push(Block {
                unknowns,
                matrix: Arc::clone(&matrices.capacity),
            });
        }
        let (advection_blocks, inflow_enthalpy) = match &spec.flow {
            Some(flow) => advection::flow_blocks(mesh, &dofs, &spaces, spec, flow, &mut load),
            None => (Vec::new(), 0.0),
        };
        conductivity_blocks.extend(advection_blocks.iter().cloned());
        let mut held: Vec<Option<f64>> = vec![None; n_full];
        for (piece, condition) in &spec.edges {
            match *condition {
                EdgeCondition::Convection {
                    coefficient,
                    ambient,
                } => conductivity_blocks.push(convection_block(
                    mesh,
                    &dofs,
                    &spaces,
                    piece,
                    spec.thickness * coefficient,
                    ambient,
                    &mut load,
                )),
                EdgeCondition::Temperature(value) => {
                    if piece.t != [-1.0, 1.0] {
                        return Err(ConductionError::PartialHeld {
                            body: spec.name.clone(),
                            element: piece.element,
                            from: piece.t[0],
                            to: piece.t[1],
                        });
                    }
                    let trace = spaces.basis(piece.element).edge_trace(piece.local);
                    let unknowns = spaces.unknowns(mesh, &dofs, piece.element);
                    for (k, &mode) in trace.iter().enumerate() {
                        // Vertex modes take the value; edge modes are zero for a constant.
                        held[unknowns[mode].0] = Some(if k < 2 { value } else { 0.0 });
                    }
                }
            }
        }
        let mut free_of = vec![usize::MAX; n_full];
        let mut n_free = 0;
        for (i, h) in held.iter().enumerate() {
            if h.is_none() {
                free_of[i] = n_free;
                n_free += 1;
            }
        }
        // The held temperatures' lift: f_free − K_free,held T_held.
        let held_values: Vec<f64> = held.iter().map(|h| h.unwrap_or(0.0)).collect();
        let full_k = BlockOperator {
            size: n_full,
            blocks: conductivity_blocks,
        };
        let lift = full_k.apply_vector(&held_values);
        let mut free_load = vec![0.0; n_free];
        for i in 0..n_full {
            if free_of[i] != usize::MAX {
                free_load[free_of[i]] = load[i] - lift[i];
            }
        }
        let has_exit = spec.faces.is_some_and(|f| f.coefficient > 0.0)
            || advection_blocks.len() > mesh.elements.len()
            || spec.edges.iter().any(|(_, c)| match c {
                EdgeCondition::Temperature(_) => true,
                EdgeCondition::Convection { coefficient, .. } => *coefficient > 0.0,
            });
        Ok(ConductionBody {
            name: spec.name.clone(),
            mesh: mesh.clone(),
            spaces,
            dofs,
            thickness: spec.thickness,
            free_of,
            held,
            conductivity_blocks: full_k.blocks,
            capacity_blocks,
            load: free_load,
            full_load: load,
            free_matrices: OnceLock::new(),
            edges: spec.edges.clone(),
            faces: spec.faces,
            has_exit,
            n_free,
            advection_blocks,
            inflow_enthalpy,
        })
    }

    /// K and C over the free unknowns, numbered from `offset` in a system of `size`
    /// unknowns, as blocks (held unknowns take sign 0, so that they drop out).
    pub fn free_operators(&self, offset: usize, size: usize) -> (BlockOperator, BlockOperator) {
        let restrict = |blocks: &[Block]| BlockOperator {
            size,
            blocks: blocks
                .iter()
                .map(|b| Block {
                    unknowns: b
                        .unknowns
                        .iter()
                        .map(|&(g, s)| match self.free_index(g) {
                            Some(f) => (offset + f, s),
                            None => (offset, 0.0),
                        })
                        .collect(),
                    matrix: Arc::clone(&b.matrix),
                })
                .collect(),
        };
        (
            restrict(&self.conductivity_blocks),
            restrict(&self.capacity_blocks),
        )
    }

    /// K and C over the free unknowns on their common pattern (assembled on first use).
    pub fn matrices(&self) -> &PairedMatrices {
        self.free_matrices.get_or_init(|| {
            let (k, c) = self.free_operators(0, self.n_free);
            assemble_pair(&k, &c)
        })
    }

    /// Whether K is symmetric: the material is at rest (advection makes K non-symmetric, to
    /// be factorised by LU).
    pub fn is_symmetric(&self) -> bool {
        self.advection_blocks.is_empty()
    }

    /// K over the free unknowns (mW/K), both triangles, on the pattern it shares with C.
    pub fn conductivity(&self) -> &SparseColMat<usize, f64> {
        &self.matrices().first
    }

    /// C over the free unknowns (mJ/K), both triangles, on the pattern it shares with K.
    pub fn capacity(&self) -> &SparseColMat<usize, f64> {
        &self.matrices().second
    }

    /// Number of free unknowns.
    pub fn n_free(&self) -> usize {
        self.n_free
    }

    /// Number of full unknowns (held ones included).
    pub fn n_full(&self) -> usize {
        self.free_of.len()
    }

    /// The full field (°C per full unknown) of free values `free`.
    pub fn expand(&self, free: &[f64]) -> Vec<f64> {
        self.free_of
            .iter()
            .zip(&self.held)
            .map(|(&f, h)| {
                if f == usize::MAX {
                    h.unwrap_or(0.0)
                } else {
                    free[f]
                }
            })
            .collect()
    }

    /// The free values of a full field.
    pub fn restrict(&self, full: &[f64]) -> Vec<f64> {
        let mut free = vec![0.0; self.n_free()];
        for (i, &f) in self.free_of.iter().enumerate() {
            if f != usize::MAX {
                free[f] = full[i];
            }
        }
        free
    }

    /// The free index of full unknown `i`, if it is free.
    pub fn free_index(&self, i: usize) -> Option<usize> {
        (self.free_of[i] != usize::MAX).then_some(self.free_of[i])
    }

    /// The field of a uniform temperature `value` (°C) over the full unknowns: the vertex
    /// modes carry it, every other mode is zero (the vertex modes sum to one).
    pub fn uniform(&self, value: f64) -> Vec<f64> {
        let mut field = vec![0.0; self.n_full()];
        for v in 0..self.mesh.vertices.len() {
            field[self.dofs.vertex_dof(v, 0)] = value;
        }
        field
    }

    /// The temperature at edge parameter `t` of local edge `local` of `element` as a
    /// combination of full unknowns: (unknown, coefficient) pairs.
    pub fn edge_trace(&self, element: usize, local: usize, t: f64) -> Vec<(usize, f64)> {
        let (xi, eta) = Mesh::edge_reference_point(local, t);
        self.point_trace(element, xi, eta)
            .into_iter()
            .filter(|&(_, c)| c != 0.0)
            .collect()
    }

    /// The temperature at reference point (ξ, η) of `element` as (unknown, coefficient) pairs.
    pub fn point_trace(&self, element: usize, xi: f64, eta: f64) -> Vec<(usize, f64)> {
        let tab = self.spaces.basis(element).tabulate(&[xi], &[eta]);
        self.spaces
            .unknowns(&self.mesh, &self.dofs, element)
            .into_iter()
            .zip(&tab.values)
            .map(|((g, s), &v)| (g, s * v))
            .collect()
    }

    /// The temperature (°C) of full field `field` at point `x` (mm), None outside the body.
    pub fn value_at(&self, field: &[f64], x: Point) -> Option<f64> {
        let (element, xi, eta) = self.mesh.locate(x)?;
        Some(
            self.point_trace(element, xi, eta)
                .iter()
                .map(|&(g, c)| c * field[g])
                .sum(),
        )
    }

    /// The stationary temperature (full field, °C) under the constant sources plus `flux`
    /// (mW per full unknown, e.g. from [`ConductionBody::edge_flux_load`]). Fails if no heat
    /// can leave the body (K singular).
    pub fn stationary(&self, flux: &[f64]) -> Result<Vec<f64>, ConductionError> {
        let mut rhs = self.load.clone();
        for (i, &f) in self.free_of.iter().enumerate() {
            if f != usize::MAX {
                rhs[f] += flux[i];
            }
        }
        let solved = if self.is_symmetric() {
            transient::solve_spd(self.conductivity(), &rhs)
        } else {
            transient::solve_general(self.conductivity(), &rhs)
        };
        let solved = solved.ok_or_else(|| {
            ConductionError::Numerical {
                body: self.name.clone(),
                message: "the conductivity matrix is singular: no edge holds a temperature or convects, so the heat cannot leave and there is no stationary temperature".into(),
            }
        })?;
        Ok(self.expand(&solved))
    }

    /// The load (mW per full unknown) of a uniform inward flux `q` (mW/mm²) on `piece`.
    pub fn edge_flux_load(&self, piece: &EdgePiece, q: f64) -> Vec<f64> {
        let mut load = vec![0.0; self.n_full()];
        for (tp, ds) in piece_quadrature(&self.mesh, piece, self.spaces.p() + 2) {
            for (g, c) in self.edge_trace(piece.element, piece.local, tp) {
                load[g] += q * c * ds * self.thickness;
            }
        }
        load
    }
}

#[cfg(test)]
mod tests;
