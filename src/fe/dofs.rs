//! Global numbering of the boundary (vertex and edge) degrees of freedom and the sparsity
//! pattern of the condensed stiffness matrix.
//!
//! Internal modes are condensed element by element and never numbered globally. The remaining
//! unknowns belong to *entities*: a vertex carries 2 dofs (u_x, u_z), an edge 2(p−1) (degree
//! 2..=p, each u_x then u_z); a scalar field (the temperature, [`DofMap::scalar`]) has one
//! component, so its numbering is the vector one halved. An entity's dofs are consecutive, so every pair of neighbouring
//! entities owns a dense block of the matrix: assembly adds whole blocks, no per-entry search.

use crate::mesh::{Mesh, EDGE_ENDPOINTS};

/// Global numbering of the boundary dofs of one body.
#[derive(Clone, Debug)]
pub struct DofMap {
    /// Polynomial degree p.
    pub p: usize,
    /// First dof of each entity (vertices first, then edges); last entry = number of dofs.
    pub entity_offset: Vec<usize>,
    /// Number of vertices (entity ids below it are vertices).
    pub n_vertices: usize,
    /// Components per mode: 2 for a displacement (x, z), 1 for a temperature.
    pub components: usize,
}

/// One element's boundary dofs in element order (mode-major: mode a, component c → 2a + c;
/// a for a scalar field).
#[derive(Clone, Debug)]
pub struct ElementDofs {
    /// Global dof of each local boundary dof.
    pub global: Vec<usize>,
    /// ±1: odd edge modes flip when the local edge runs against the global orientation.
    pub sign: Vec<f64>,
    /// The element's 8 entities: 4 vertices, then the 4 edges (as entity ids).
    pub entities: [usize; 8],
}

impl DofMap {
    /// Number the displacement dofs (x, z) of `mesh` at degree `p`.
    pub fn new(mesh: &Mesh, p: usize) -> DofMap {
        Self::with_components(mesh, p, 2)
    }

    /// Number the dofs of a scalar field (one per mode) of `mesh` at degree `p`.
    pub fn scalar(mesh: &Mesh, p: usize) -> DofMap {
        Self::with_components(mesh, p, 1)
    }

    fn with_components(mesh: &Mesh, p: usize, components: usize) -> DofMap {
        let mut entity_offset = Vec::with_capacity(mesh.vertices.len() + mesh.edges.len() + 1);
        let mut next = 0;
        for _ in &mesh.vertices {
            entity_offset.push(next);
            next += components;
        }
        for _ in &mesh.edges {
            entity_offset.push(next);
            next += components * (p - 1);
        }
        entity_offset.push(next);
        DofMap {
            p,
            entity_offset,
            n_vertices: mesh.vertices.len(),
            components,
        }
    }

    /// Total number of global (boundary) dofs.
    pub fn n_dofs(&self) -> usize {
        *self.entity_offset.last().unwrap()
    }

    /// Number of entities (vertices + edges).
    pub fn n_entities(&self) -> usize {
        self.entity_offset.len() - 1
    }

    /// Global dof of component `c` (0 = x, 1 = z) at vertex `v`.
    pub fn vertex_dof(&self, v: usize, c: usize) -> usize {
        self.entity_offset[v] + c
    }

    /// Global dof of component `c` of the degree-`k` mode (2 ≤ k ≤ p) on global edge `e`.
    pub fn edge_dof(&self, e: usize, k: usize, c: usize) -> usize {
        self.entity_offset[self.n_vertices + e] + self.components * (k - 2) + c
    }

    /// Boundary dofs of element `element`, in the order of [`crate::basis::QuadBasis`] modes.
    pub fn element_dofs(&self, mesh: &Mesh, element: usize) -> ElementDofs {
        let el = &mesh.elements[element];
        let p = self.p;
        let mut global = Vec::with_capacity(4 * self.components * p);
        let mut sign = Vec::with_capacity(4 * self.components * p);
        for &v in &el.vertices {
            for c in 0..self.components {
                global.push(self.vertex_dof(v, c));
                sign.push(1.0);
            }
        }
        for (local, &edge) in el.edges.iter().enumerate() {
            let (a, b) = EDGE_ENDPOINTS[local];
            let reversed = el.vertices[a] > el.vertices[b];
            for k in 2..=p {
                let s = if reversed && k % 2 == 1 { -1.0 } else { 1.0 };
                for c in 0..self.components {
                    global.push(self.edge_dof(edge, k, c));
                    sign.push(s);
                }
            }
        }
        let mut entities = [0; 8];
        entities[..4].copy_from_slice(&el.vertices);
        for e in 0..4 {
            entities[4 + e] = self.n_vertices + el.edges[e];
        }
        ElementDofs {
            global,
            sign,
            entities,
        }
    }
}

/// Compressed-column pattern of the lower triangle of the (symmetric) condensed stiffness,
/// built entity-wise. The upper triangle is left out: the factorisation reads only the lower
/// one, and storing both doubled the memory the set-up touches (at 513 contact points
/// 1.6 million entries for the punch, 25 MB with the row indices).
#[derive(Clone, Debug)]
pub struct Pattern {
    /// Column pointers (length n + 1).
    pub col_ptr: Vec<usize>,
    /// Row indices, sorted within each column.
    pub row_idx: Vec<usize>,
    /// For each entity, its neighbour entities (sorted, itself included).
    pub neighbours: Vec<Vec<usize>>,
    /// For each entity, the row offset of each later neighbour's block within its columns,
    /// counted from the end of the entity's own rows (0 for itself and earlier neighbours,
    /// which have no rows there).
    pub neighbour_row_offset: Vec<Vec<usize>>,
    /// First dof of each entity (and the number of dofs at the end).
    entity_offset: Vec<usize>,
}

impl Pattern {
    /// Pattern for all elements of `mesh` numbered by `dofs`.
    pub fn new(mesh: &Mesh, dofs: &DofMap) -> Pattern {
        let n_entities = dofs.n_entities();
        let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); n_entities];
        for element in 0..mesh.elements.len() {
            let entities = dofs.element_dofs(mesh, element).entities;
            for &a in &entities {
                neighbours[a].extend_from_slice(&entities);
            }
        }
        let size = |e: usize| dofs.entity_offset[e + 1] - dofs.entity_offset[e];
        let mut neighbour_row_offset = Vec::with_capacity(n_entities);
        for (e, list) in neighbours.iter_mut().enumerate() {
            list.sort_unstable();
            list.dedup();
            let mut offsets = Vec::with_capacity(list.len());
            let mut acc = 0;
            for &f in list.iter() {
                offsets.push(acc);
                if f > e {
                    acc += size(f);
                }
            }
            neighbour_row_offset.push(offsets);
        }
        let n = dofs.n_dofs();
        let offset = &dofs.entity_offset;
        let mut col_ptr = Vec::with_capacity(n + 1);
        // Grown, not sized up front: an exact allocation changed glibc's trimming of the heap
        // so that repeated set-ups in one process (the benchmarks) faulted in their element
        // matrices afresh every time (170 000 page faults in 3 s against 9 000).
        let mut row_idx = Vec::new();
        col_ptr.push(0);
        for (e, list) in neighbours.iter().enumerate() {
            for d in offset[e]..offset[e + 1] {
                row_idx.extend(d..offset[e + 1]);
                for &f in list.iter().filter(|&&f| f > e) {
                    row_idx.extend(offset[f]..offset[f + 1]);
                }
                col_ptr.push(row_idx.len());
            }
        }
        Pattern {
            col_ptr,
            row_idx,
            neighbours,
            neighbour_row_offset,
            entity_offset: offset.clone(),
        }
    }

    /// Position in the value array of the first stored row of entity `row_entity` in column
    /// `col` (a dof of entity `col_entity`, `row_entity` ≥ `col_entity`), and the index of that
    /// row within the entity's block: the diagonal block starts at the diagonal.
    pub fn block_start(&self, col: usize, col_entity: usize, row_entity: usize) -> (usize, usize) {
        if row_entity == col_entity {
            return (self.col_ptr[col], col - self.entity_offset[col_entity]);
        }
        let k = self.neighbours[col_entity]
            .binary_search(&row_entity)
            .expect("entities of one element are neighbours");
        let own = self.entity_offset[col_entity + 1] - col;
        (
            self.col_ptr[col] + own + self.neighbour_row_offset[col_entity][k],
            0,
        )
    }
}
