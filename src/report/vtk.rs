//! ParaView output: VTK XML unstructured grids (`.vtu`, ASCII) of the bodies and of the
//! contact line, and a `.pvd` collection that plays them in time order.
//!
//! Coordinates are written as (x, z, 0), so ParaView's default x–y view shows the model as
//! drawn in the problem file; vectors likewise as (u_x, u_z, 0). The points are the undeformed
//! geometry: ParaView's *Warp By Vector* on `displacement` (with a scale factor, the
//! displacements are micrometres on a model of centimetres) shows the deformed shape.
//!
//! A p-version element carries polynomials of degree p, so each element is sampled on the
//! (m + 1) × (m + 1) Gauss–Lobatto grid of reference points (m = max(p, 2)) and written as
//! m × m linear sub-quadrilaterals; the contact points (Lobatto points of body 1's edge) are
//! sample points, and the sub-cells are finest at the element edges where the fields vary
//! most. Points are not shared between elements: stresses are discontinuous
//! across element edges and ParaView shows them as computed.

use crate::deformation::BodyField;
use crate::elasticity::ElasticBody;
use crate::geometry::Point;
use crate::material::Analysis;
use std::fmt::Write as _;
use std::path::Path;

mod jobs;
mod sliding;
pub use jobs::{
    write_contact_job, write_contact_states, write_elastic, write_run, write_steady, ContactState,
    VtkError, PVD_NAME,
};
pub use sliding::write_sliding;

/// One body to write: the factorised body, its displacement field and its number (1, 2, …).
pub struct VtkBody<'a> {
    /// The body (mesh, basis, materials).
    pub body: &'a ElasticBody,
    /// Its displacement field.
    pub field: &'a BodyField,
    /// Body number written as cell data `body` (1 = the contact body, 2 = its partner).
    pub id: i32,
}

/// The contact line at one state: the contact points of body 1 and their values.
pub struct VtkContact<'a> {
    /// Contact points [x, z], mm, in order along the edge.
    pub x: &'a [Point],
    /// Displacement of body 1 at each point, mm.
    pub displacement: &'a [Point],
    /// Named point values, one per point (pressure MPa, gap mm, wear mm, …).
    pub values: Vec<(&'a str, &'a [f64])>,
}

/// Von Mises equivalent stress (MPa) of the in-plane stress [σ_xx, σ_zz, σ_xz]; under plane
/// strain with σ_yy = ν (σ_xx + σ_zz), under plane stress with σ_yy = 0.
pub fn von_mises(stress: [f64; 3], analysis: Analysis, poisson: f64) -> f64 {
    von_mises_heated(stress, analysis, poisson, 0.0, 0.0)
}

/// [`von_mises`] of a heated body: in plane strain, ε_yy = 0 holds back the out-of-plane
/// thermal expansion, so σ_yy = ν (σ_xx + σ_zz) − E α ΔT; `held_back` is E α ΔT (MPa, 0 in
/// plane stress, where σ_yy = 0 whatever the temperature). A free block heated uniformly in
/// plane strain has σ_yy = −E α ΔT and a von Mises stress of E α ΔT, not zero.
///
/// An axisymmetric body's third normal stress is its hoop stress `hoop` (MPa).
pub fn von_mises_heated(
    stress: [f64; 3],
    analysis: Analysis,
    poisson: f64,
    held_back: f64,
    hoop: f64,
) -> f64 {
    let [sx, sz, sxz] = stress;
    let sy = match analysis {
        Analysis::PlaneStress { .. } => 0.0,
        Analysis::PlaneStrain { .. } => poisson * (sx + sz) - held_back,
        Analysis::Axisymmetric => hoop,
    };
    (0.5 * ((sx - sy).powi(2) + (sy - sz).powi(2) + (sz - sx).powi(2)) + 3.0 * sxz * sxz).sqrt()
}

/// Number of sub-cells per element side for degree `p`.
pub fn subdivisions(p: usize) -> usize {
    p.max(2)
}

#[derive(Default)]
struct Grid {
    points: Vec<[f64; 2]>,
    displacement: Vec<[f64; 2]>,
    stress: Vec<[f64; 3]>,
    von_mises: Vec<f64>,
    /// Hoop stress σ_θθ, MPa (bodies of revolution; zero in a plane analysis, not written).
    hoop: Vec<f64>,
    /// Whether any body is a body of revolution.
    axisymmetric: bool,
    /// °C where the body has a temperature (NaN elsewhere, never written then).
    temperature: Vec<f64>,
    cells: Vec<[usize; 4]>,
    material: Vec<i32>,
    body: Vec<i32>,
}

impl Grid {
    fn add(&mut self, b: &VtkBody) {
        let body = b.body;
        self.axisymmetric |= body.analysis.is_axisymmetric();
        let m = subdivisions(body.dofs.p);
        let mut nodes = crate::quadrature::gauss_lobatto(m + 1).points;
        nodes.sort_by(f64::total_cmp);
        for element in 0..body.mesh.elements.len() {
            let first = self.points.len();
            let material = body.mesh.elements[element].material;
            let poisson = body.materials[material].poisson;
            for j in 0..=m {
                for i in 0..=m {
                    let (xi, eta) = (nodes[i], nodes[j]);
                    let v = b.field.values_at_reference(body, element, xi, eta);
                    self.points.push(body.mesh.map(element, xi, eta));
                    self.displacement.push(v.displacement);
                    self.stress.push(v.stress);
                    self.hoop.push(v.hoop[1]);
                    let held_back = b.field.held_back_stress(body, element, xi, eta);
                    self.von_mises.push(von_mises_heated(
                        v.stress,
                        body.analysis,
                        poisson,
                        held_back,
                        v.hoop[1],
                    ));
                    self.temperature.push(
                        b.field
                            .temperature_at_reference(body, element, xi, eta)
                            .unwrap_or(f64::NAN),
                    );
                }
            }
            let at = |i: usize, j: usize| first + j * (m + 1) + i;
            for j in 0..m {
                for i in 0..m {
                    // Counter-clockwise in (ξ, η), as VTK_QUAD expects.
                    self.cells
                        .push([at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
                    self.material.push(material as i32);
                    self.body.push(b.id);
                }
            }
        }
    }
}

fn data_array(out: &mut String, name: &str, kind: &str, components: usize, values: &[String]) {
    let _ = writeln!(
        out,
        r#"        <DataArray type="{kind}" Name="{name}" NumberOfComponents="{components}" format="ascii">"#
    );
    for chunk in values.chunks(6 * components) {
        let _ = writeln!(out, "          {}", chunk.join(" "));
    }
    out.push_str("        </DataArray>\n");
}

/// Full precision, and never NaN in a file: ParaView reads "nan" but a reader test would not
/// notice it, so a non-finite value is written as 0 and reported by the caller's checks.
fn real(x: f64) -> String {
    if x.is_finite() {
        format!("{x:e}")
    } else {
        "0".into()
    }
}

fn vectors(v: &[[f64; 2]]) -> Vec<String> {
    v.iter()
        .flat_map(|p| [real(p[0]), real(p[1]), "0".to_string()])
        .collect()
}

fn scalars(v: &[f64]) -> Vec<String> {
    v.iter().map(|&x| real(x)).collect()
}

/// An unstructured grid with `points`, cells of VTK type `cell_type` (all `nodes` long),
/// point data and cell data, as one VTK XML document.
struct Piece<'a> {
    points: &'a [[f64; 2]],
    cells: Vec<Vec<usize>>,
    cell_type: u8,
    point_vectors: Vec<(&'a str, &'a [[f64; 2]])>,
    point_scalars: Vec<(&'a str, Vec<f64>)>,
    cell_ints: Vec<(&'a str, &'a [i32])>,
}

impl Piece<'_> {
    fn xml(&self) -> String {
        let mut out = String::new();
        out.push_str("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n");
        let _ = writeln!(
            out,
            r#"    <Piece NumberOfPoints="{}" NumberOfCells="{}">"#,
            self.points.len(),
            self.cells.len()
        );
        out.push_str("      <PointData>\n");
        for (name, v) in &self.point_vectors {
            data_array(&mut out, name, "Float64", 3, &vectors(v));
        }
        for (name, v) in &self.point_scalars {
            data_array(&mut out, name, "Float64", 1, &scalars(v));
        }
        out.push_str("      </PointData>\n      <CellData>\n");
        for (name, v) in &self.cell_ints {
            let s: Vec<String> = v.iter().map(|i| i.to_string()).collect();
            data_array(&mut out, name, "Int32", 1, &s);
        }
        out.push_str("      </CellData>\n      <Points>\n");
        data_array(&mut out, "Points", "Float64", 3, &vectors(self.points));
        out.push_str("      </Points>\n      <Cells>\n");
        let connectivity: Vec<String> =
            self.cells.iter().flatten().map(|i| i.to_string()).collect();
        data_array(&mut out, "connectivity", "Int64", 1, &connectivity);
        let mut end = 0;
        let offsets: Vec<String> = self
            .cells
            .iter()
            .map(|c| {
                end += c.len();
                end.to_string()
            })
            .collect();
        data_array(&mut out, "offsets", "Int64", 1, &offsets);
        let types = vec![self.cell_type.to_string(); self.cells.len()];
        data_array(&mut out, "types", "UInt8", 1, &types);
        out.push_str("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
        out
    }
}

const VTK_LINE: u8 = 3;
const VTK_QUAD: u8 = 9;

/// Write the bodies as one `.vtu` file: point data `displacement` (mm, 3 components),
/// `stress_xx`, `stress_zz`, `stress_xz`, `von_mises` (MPa; with heat the stress is
/// D (ε − ε_th), thermal stresses included), `stress_hoop` (MPa, bodies of revolution), with
/// heat `temperature` (°C); cell data
/// `material` (index in the problem's materials, alphabetical) and `body`.
pub fn write_bodies(path: &Path, bodies: &[VtkBody]) -> std::io::Result<()> {
    let mut grid = Grid::default();
    for b in bodies {
        grid.add(b);
    }
    let component = |c: usize| grid.stress.iter().map(|s| s[c]).collect::<Vec<f64>>();
    let piece = Piece {
        points: &grid.points,
        cells: grid.cells.iter().map(|c| c.to_vec()).collect(),
        cell_type: VTK_QUAD,
        point_vectors: vec![("displacement", &grid.displacement)],
        point_scalars: vec![
            ("stress_xx", component(0)),
            ("stress_zz", component(1)),
            ("stress_xz", component(2)),
            ("von_mises", grid.von_mises.clone()),
        ],
        cell_ints: vec![("material", &grid.material), ("body", &grid.body)],
    };
    let mut piece = piece;
    if grid.axisymmetric {
        piece.point_scalars.push(("stress_hoop", grid.hoop.clone()));
    }
    if grid.temperature.iter().all(|t| t.is_finite()) && !grid.temperature.is_empty() {
        piece
            .point_scalars
            .push(("temperature", grid.temperature.clone()));
    }
    write(path, &piece.xml())
}

/// Write the contact line as a `.vtu` file of line segments between consecutive contact
/// points: point data `displacement` (body 1, mm) and each of `contact.values`.
pub fn write_contact(path: &Path, contact: &VtkContact) -> std::io::Result<()> {
    let n = contact.x.len();
    let piece = Piece {
        points: contact.x,
        cells: (1..n).map(|i| vec![i - 1, i]).collect(),
        cell_type: VTK_LINE,
        point_vectors: vec![("displacement", contact.displacement)],
        point_scalars: contact
            .values
            .iter()
            .map(|(name, v)| (*name, v.to_vec()))
            .collect(),
        cell_ints: vec![],
    };
    write(path, &piece.xml())
}

/// One data set of a `.pvd` collection: time (half periods, or 0), part and file name
/// relative to the `.pvd` file.
pub struct PvdEntry {
    /// Time value shown by ParaView (half periods for a wear run).
    pub time: f64,
    /// Part number (0 = bodies, 1 = contact line).
    pub part: usize,
    /// File name relative to the collection.
    pub file: String,
}

/// Write a `.pvd` collection of `entries`.
pub fn write_pvd(path: &Path, entries: &[PvdEntry]) -> std::io::Result<()> {
    let mut out = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n",
    );
    for e in entries {
        let _ = writeln!(
            out,
            r#"    <DataSet timestep="{}" group="" part="{}" file="{}"/>"#,
            e.time, e.part, e.file
        );
    }
    out.push_str("  </Collection>\n</VTKFile>\n");
    write(path, &out)
}

fn write(path: &Path, text: &str) -> std::io::Result<()> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::write(path, text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn von_mises_of_uniaxial_and_pure_shear() {
        let stress = Analysis::PlaneStress { thickness: 1.0 };
        // Uniaxial σ: σ_vM = σ; pure shear τ: σ_vM = √3 τ.
        assert!((von_mises([100.0, 0.0, 0.0], stress, 0.3) - 100.0).abs() < 1e-12);
        assert!((von_mises([0.0, 0.0, 10.0], stress, 0.3) - 10.0 * 3f64.sqrt()).abs() < 1e-12);
        // Plane strain, equibiaxial σ with ν = 0.5: σ_yy = σ, hydrostatic, σ_vM = 0.
        let strain = Analysis::PlaneStrain { thickness: 1.0 };
        assert!(von_mises([50.0, 50.0, 0.0], strain, 0.5).abs() < 1e-12);
    }

    #[test]
    fn a_heated_plane_strain_body_carries_its_held_back_stress() {
        // A free block heated by ΔT in plane strain: σ_xx = σ_zz = σ_xz = 0, σ_yy = −E α ΔT,
        // so its von Mises stress is E α ΔT (e.g. 2e5 · 1.2e-5 · 50 = 120 MPa); in plane
        // stress nothing holds it back.
        let strain = Analysis::PlaneStrain { thickness: 1.0 };
        let stress = Analysis::PlaneStress { thickness: 1.0 };
        assert!((von_mises_heated([0.0; 3], strain, 0.3, 120.0, 0.0) - 120.0).abs() < 1e-12);
        assert_eq!(von_mises_heated([0.0; 3], stress, 0.3, 120.0, 0.0), 0.0);
    }
}
