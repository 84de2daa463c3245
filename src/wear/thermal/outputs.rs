//! The outputs of the heat problem as linear maps of its unknowns, in the form that costs
//! least: temperatures at points (contact points, partners, probes, boundary samples) are
//! sparse rows (a point's trace touches one element's modes); the thermal gap is kept as the
//! elastic adjoints X = K⁻¹N and the elements' thermal load matrices, and applied element by
//! element. A dense gap matrix (points × unknowns) took 51 MB at 32 contact elements and
//! would take 400 MB at 64; the element-wise form keeps only X.

use super::Affine;
use crate::conduction::blocks::for_column_ranges;
use crate::conduction::reduced::ReducedModel;
use crate::conduction::ConductionBody;
use crate::contact::CondensedContact;
use crate::elasticity::{ElasticBody, ThermalLoads};
use crate::quadrature::gauss_lobatto;
use faer::linalg::matmul::matmul;
use faer::{Accum, Mat, MatMut, MatRef, Par};

/// y = M T + c with M given by sparse rows over the combined free unknowns.
#[derive(Clone, Debug, Default)]
pub struct Output {
    /// Each output's (unknown, coefficient) pairs.
    pub rows: Vec<Vec<(usize, f64)>>,
    /// c: the part of the held temperatures (and of the reference).
    pub offset: Vec<f64>,
}

impl Output {
    /// The outputs of field `t` (combined free unknowns).
    pub fn at(&self, t: &[f64]) -> Vec<f64> {
        self.rows
            .iter()
            .zip(&self.offset)
            .map(|(row, c)| c + row.iter().map(|&(g, v)| v * t[g]).sum::<f64>())
            .collect()
    }

    /// The output in the modes of `model`: M Φ, gathered row by row.
    pub fn reduce(&self, model: &ReducedModel) -> Affine {
        let r = model.len();
        let mut matrix = Mat::<f64>::zeros(self.rows.len(), r);
        for j in 0..r {
            let column = model.modes.col(j);
            for (i, row) in self.rows.iter().enumerate() {
                matrix[(i, j)] = row.iter().map(|&(g, v)| v * column[g]).sum();
            }
        }
        Affine {
            matrix,
            offset: self.offset.clone(),
        }
    }
}

/// One element of a [`GapBody`]: its elastic boundary dofs (dof, sign), its temperature
/// unknowns (combined free index and sign; sign 0 where held) and its thermal load matrix's
/// index in the body's `loads`.
type GapElement = (Vec<(usize, f64)>, Vec<(usize, f64)>, usize);

/// One body's part of the thermal gap: its elements' thermal loads seen through its adjoint.
#[derive(Clone, Debug)]
struct GapBody {
    /// Xᵀ (points × the body's elastic boundary dofs), times the gap's sign for the body
    /// (+ body 2, − body 1).
    adjoint: Mat<f64>,
    /// Its elements.
    elements: Vec<GapElement>,
    /// The condensed thermal load per unit temperature of each mode, per element type (N/K).
    loads: Vec<Mat<f64>>,
}

/// The thermal gap u_n⁽²⁾ − u_n⁽¹⁾ (mm) at each contact point as a linear map of the
/// temperature: Σ_bodies ± Xᵀ F (T − T_ref).
#[derive(Clone, Debug)]
pub struct GapOutput {
    bodies: Vec<GapBody>,
    /// The held temperatures' and the reference temperature's part, mm.
    pub offset: Vec<f64>,
}

impl GapOutput {
    /// The gap of the columns of `t` (combined free unknowns × r): points × r, the columns
    /// in ranges on all threads.
    fn apply(&self, t: MatRef<'_, f64>) -> Mat<f64> {
        let mut out = Mat::<f64>::zeros(self.offset.len(), t.ncols());
        for_column_ranges(out.as_mut(), |range, part| {
            self.add_applied(t.subcols(range.start, range.len()), part)
        });
        out
    }

    /// out += the gap of the columns of `t`.
    fn add_applied(&self, t: MatRef<'_, f64>, mut out: MatMut<'_, f64>) {
        let (n, r) = (self.offset.len(), t.ncols());
        let mut gathered = Mat::<f64>::zeros(0, r);
        let mut load = Mat::<f64>::zeros(0, r);
        let mut adjoint = Mat::<f64>::zeros(n, 0);
        for body in &self.bodies {
            for (dofs, unknowns, ty) in &body.elements {
                gathered.resize_with(unknowns.len(), r, |_, _| 0.0);
                for c in 0..r {
                    let column = t.col(c);
                    for (a, &(g, s)) in unknowns.iter().enumerate() {
                        gathered[(a, c)] = if s == 0.0 { 0.0 } else { s * column[g] };
                    }
                }
                let matrix = &body.loads[*ty];
                load.resize_with(matrix.nrows(), r, |_, _| 0.0);
                matmul(
                    load.as_mut(),
                    Accum::Replace,
                    matrix,
                    &gathered,
                    1.0,
                    Par::Seq,
                );
                adjoint.resize_with(n, dofs.len(), |_, _| 0.0);
                for (k, &(d, s)) in dofs.iter().enumerate() {
                    let source = body.adjoint.col(d);
                    let mut target = adjoint.col_mut(k);
                    for i in 0..n {
                        target[i] = s * source[i];
                    }
                }
                matmul(out.as_mut(), Accum::Add, &adjoint, &load, 1.0, Par::Seq);
            }
        }
    }

    /// The thermal gap of field `t` (combined free unknowns), mm.
    pub fn at(&self, t: &[f64]) -> Vec<f64> {
        let column = MatRef::from_column_major_slice(t, t.len(), 1);
        let g = self.apply(column);
        (0..self.offset.len())
            .map(|i| g[(i, 0)] + self.offset[i])
            .collect()
    }

    /// The gap in the modes of `model`.
    pub fn reduce(&self, model: &ReducedModel) -> Affine {
        Affine {
            matrix: self.apply(model.modes.as_ref()),
            offset: self.offset.clone(),
        }
    }
}

/// The thermal gap of the two bodies: `elastic` as the contact built them (body 1 clamped
/// at its plate edge), `thermal` their conduction operators with their free unknowns from
/// `offsets` in the combined numbering, `loads` their thermal load operators and
/// `reference` the stress-free temperature (°C).
pub fn thermal_gap(
    elastic: [&ElasticBody; 2],
    thermal: &[ConductionBody; 2],
    contact: &CondensedContact,
    offsets: [usize; 2],
    loads: [&ThermalLoads; 2],
    reference: f64,
) -> Result<GapOutput, (String, String)> {
    let n = contact.len();
    let mut bodies = Vec::with_capacity(2);
    let mut offset = vec![0.0; n];
    for b in 0..2 {
        let body = elastic[b];
        let heat = &thermal[b];
        let error = |e: crate::elasticity::ElasticityError| (body.name.clone(), e.to_string());
        let loads = loads[b];
        // X = K⁻¹ N: the displacement of a unit normal force at each contact point's trace.
        let mut x = Mat::<f64>::zeros(body.dofs.n_dofs(), n);
        for (i, trace) in contact.traces[b].iter().enumerate() {
            let normal = contact.points.normal[i];
            for &(g, c) in trace {
                x[(g[0], i)] += c * normal[0];
                x[(g[1], i)] += c * normal[1];
            }
        }
        body.solve_in_place(&mut x).map_err(error)?;
        let sign = if b == 0 { -1.0 } else { 1.0 };
        let adjoint = Mat::from_fn(n, x.nrows(), |i, d| sign * x[(d, i)]);
        let held = heat.expand(&vec![0.0; heat.n_free()]);
        let uniform = heat.uniform(reference);
        let mut types: Vec<Option<Mat<f64>>> = Vec::new();
        let mut elements = Vec::with_capacity(body.mesh.elements.len());
        for element in 0..body.mesh.elements.len() {
            let ed = body.dofs.element_dofs(&body.mesh, element);
            let dofs: Vec<(usize, f64)> = ed
                .global
                .iter()
                .copied()
                .zip(ed.sign.iter().copied())
                .collect();
            let modes = heat.element_unknowns(element);
            let unknowns: Vec<(usize, f64)> = modes
                .iter()
                .map(|&(g, s)| match heat.free_index(g) {
                    Some(f) => (offsets[b] + f, s),
                    None => (0, 0.0),
                })
                .collect();
            let ty = loads.load_type(element);
            if types.len() <= ty {
                types.resize(ty + 1, None);
            }
            let load =
                types[ty].get_or_insert_with(|| body.thermal_load_matrix(loads, element).clone());
            // The constant part: held temperatures where held, minus the reference
            // everywhere.
            let constant: Vec<f64> = modes
                .iter()
                .map(|&(g, s)| {
                    let value = match heat.free_index(g) {
                        Some(_) => -uniform[g],
                        None => held[g] - uniform[g],
                    };
                    s * value
                })
                .collect();
            if constant.iter().any(|&c| c != 0.0) {
                for (r, &(d, ds)) in dofs.iter().enumerate() {
                    let f: f64 = (0..constant.len())
                        .map(|m| load[(r, m)] * constant[m])
                        .sum();
                    if f != 0.0 {
                        for (i, o) in offset.iter_mut().enumerate() {
                            *o += adjoint[(i, d)] * ds * f;
                        }
                    }
                }
            }
            elements.push((dofs, unknowns, ty));
        }
        bodies.push(GapBody {
            adjoint,
            elements,
            loads: types
                .into_iter()
                .map(|t| t.unwrap_or_else(|| Mat::zeros(0, 0)))
                .collect(),
        });
    }
    Ok(GapOutput { bodies, offset })
}

/// Where each body's largest temperature is looked for: the Lobatto points of its contact
/// edge (where the heat enters), and the ends and middle of every other boundary edge (held
/// and convecting edges, where a hot ambient or a held temperature can lead). A body heated
/// only at its boundary has its largest temperature on the boundary (the maximum principle).
pub(super) fn boundary_samples(
    body: &ConductionBody,
    contact_edge: &[(usize, usize)],
) -> Vec<Vec<(usize, f64)>> {
    let lobatto = gauss_lobatto(body.spaces.p() + 1).points;
    let mut samples = Vec::new();
    for (element, local, _) in crate::heat_input::boundary_edges(&body.mesh) {
        let points: &[f64] = if contact_edge.contains(&(element, local)) {
            &lobatto
        } else {
            &[-1.0, 0.0, 1.0]
        };
        for &t in points {
            samples.push(body.edge_trace(element, local, t));
        }
    }
    samples
}

/// The heat stored in `body` relative to the stress-free temperature `reference` (°C), mJ,
/// as an output over the combined free unknowns (the body's starting at `offset`).
pub(super) fn stored_output(
    body: &ConductionBody,
    held: &[f64],
    offset: usize,
    reference: f64,
) -> Output {
    let weights = body.heat_content_weights();
    let uniform = body.uniform(reference);
    let mut constant = 0.0;
    let mut row = Vec::new();
    for (g, &w) in weights.iter().enumerate() {
        match body.free_index(g) {
            Some(f) => {
                row.push((offset + f, w));
                constant -= w * uniform[g];
            }
            None => constant += w * (held[g] - uniform[g]),
        }
    }
    Output {
        rows: vec![row],
        offset: vec![constant],
    }
}
