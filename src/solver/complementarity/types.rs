//! The public types of the contact solve: its method, the sliding direction, and what a
//! solve returns.

/// How the complementarity problem is solved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Method {
    /// Active set with Lemke fallback (exact).
    ActiveSet,
    /// Lemke's method only (exact, slower).
    Lemke,
    /// Penalty regularisation with normal stiffness c_n (MPa/mm), solved exactly.
    Penalty {
        /// c_n, MPa/mm.
        stiffness: f64,
    },
}

/// Sliding direction of a half cycle: friction on body 1 is s μ p τ with s = ±1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// s = +1.
    Plus,
    /// s = −1.
    Minus,
}

impl Direction {
    /// s = ±1.
    pub fn sign(self) -> f64 {
        match self {
            Direction::Plus => 1.0,
            Direction::Minus => -1.0,
        }
    }
    /// The other direction.
    pub fn reversed(self) -> Direction {
        match self {
            Direction::Plus => Direction::Minus,
            Direction::Minus => Direction::Plus,
        }
    }
    /// "+" or "−" (U+2212, the minus sign of the issue and the paper).
    pub fn symbol(self) -> &'static str {
        match self {
            Direction::Plus => "+",
            Direction::Minus => "−",
        }
    }
    pub(super) fn index(self) -> usize {
        match self {
            Direction::Plus => 0,
            Direction::Minus => 1,
        }
    }
}

/// Outcome of a solve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Converged: residuals at round-off.
    Solved,
    /// Neither the active set nor Lemke's method found a solution; the last iterate is kept.
    Failed,
}

/// What a solve did and how well.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolveInfo {
    /// Solved or failed.
    pub status: Status,
    /// Active-set iterations (reduced-system solves).
    pub iterations: usize,
    /// Factorisations of the reduced system.
    pub factorisations: usize,
    /// Pivots of Lemke's method (0 if not used).
    pub lemke_pivots: usize,
    /// max_i |min(p_i, d_i/(A_ii w_i t))| / max p: complementarity in units of the peak pressure.
    pub complementarity: f64,
    /// |E P + L|∞ relative to the load: equilibrium of the plate.
    pub equilibrium: f64,
}

/// Pressures, gaps and rigid-body motion of one solve.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ContactSolution {
    /// Contact pressure p_i, MPa.
    pub pressure: Vec<f64>,
    /// Contact force P_i = p_i w_i t, N.
    pub force: Vec<f64>,
    /// Gap d_i after deformation, mm (negative = penetration, penalty method only).
    pub gap: Vec<f64>,
    /// Rigid plate unknowns λ (λ_F mm downwards, λ_M rad about +y).
    pub rigid: Vec<f64>,
    /// Points in contact.
    pub active: Vec<bool>,
}
