//! The polynomial space of each element of a conduction body, and where its modes sit among
//! the body's unknowns.
//!
//! # Why two spaces in one body
//!
//! Most of a p-version body's unknowns are its elements' internal modes: at p = 8 the
//! tensor-product space Q_p has 49 per element, the trunk space 15, against 32 boundary modes
//! that neighbours share. The heat problem's reduction costs in proportion to its unknowns
//! (`crate::conduction::reduced`: every Krylov block is orthogonalised over all of them), so
//! the trunk space halves it. The trunk space holds every polynomial of degree p, which is
//! what a smooth field needs; what it lacks are the products x^a z^b with a + b > p. Those
//! matter where the frictional heat enters: within a half period it warms a layer far
//! thinner than an element (0.3–2 mm under 5 mm elements on punch-b40-heat), steep in the
//! depth and, at the ends of a flat punch's contact, steep along it too. There the trunk
//! space left the contact temperature 0.08 K (3 % of the rise in the first half period)
//! above the tensor-product one, on 8 and on 16 elements alike (docs/convergence.md, "The
//! heat's element spaces"). So the elements along the contact keep the tensor-product space
//! and the rest, where the temperature is smooth, take the trunk space. The boundary modes of
//! both spaces are the same functions in the same order, so neighbours of different spaces
//! are conforming; only the number of internal modes differs.

use crate::basis::{QuadBasis, Space};
use crate::dofs::DofMap;
use crate::mesh::Mesh;

/// Each element's space and the full index of its first internal unknown.
#[derive(Clone, Debug)]
pub struct ElementSpaces {
    /// The tensor-product and the trunk basis at the body's degree.
    bases: [QuadBasis; 2],
    /// Per element: 0 for the tensor-product space, 1 for the trunk space.
    of: Vec<usize>,
    /// Per element: the full index of its first internal unknown.
    first_internal: Vec<usize>,
    /// Boundary dofs plus every element's internal modes.
    n_full: usize,
}

impl ElementSpaces {
    /// Degree `p`, `space` for every element but those listed in `tensor_elements`, which
    /// take the tensor-product space.
    pub fn new(
        mesh: &Mesh,
        dofs: &DofMap,
        p: usize,
        space: Space,
        tensor_elements: &[usize],
    ) -> Self {
        let bases = [
            QuadBasis::new(p, Space::TensorProduct),
            QuadBasis::new(p, Space::Trunk),
        ];
        let of: Vec<usize> = (0..mesh.elements.len())
            .map(|e| usize::from(space == Space::Trunk && !tensor_elements.contains(&e)))
            .collect();
        let mut first_internal = Vec::with_capacity(of.len());
        let mut next = dofs.n_dofs();
        for &s in &of {
            first_internal.push(next);
            next += bases[s].n_internal();
        }
        ElementSpaces {
            bases,
            of,
            first_internal,
            n_full: next,
        }
    }

    /// The basis of `element`.
    pub fn basis(&self, element: usize) -> &QuadBasis {
        &self.bases[self.of[element]]
    }

    /// The space of `element`.
    pub fn space(&self, element: usize) -> Space {
        self.basis(element).space
    }

    /// The space of every element.
    pub fn each(&self) -> Vec<Space> {
        (0..self.of.len()).map(|e| self.space(e)).collect()
    }

    /// The polynomial degree (the same in every element).
    pub fn p(&self) -> usize {
        self.bases[0].p
    }

    /// Boundary dofs plus every element's internal modes.
    pub fn n_full(&self) -> usize {
        self.n_full
    }

    /// The full unknown of each of `element`'s modes (in its basis's order), with its sign.
    pub fn unknowns(&self, mesh: &Mesh, dofs: &DofMap, element: usize) -> Vec<(usize, f64)> {
        let basis = self.basis(element);
        let ed = dofs.element_dofs(mesh, element);
        let nb = basis.n_boundary();
        let first_internal = self.first_internal[element];
        (0..basis.n_modes())
            .map(|a| {
                if a < nb {
                    (ed.global[a], ed.sign[a])
                } else {
                    (first_internal + a - nb, 1.0)
                }
            })
            .collect()
    }
}
