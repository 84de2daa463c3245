//! The validation cases of heat: the closed forms of conduction and thermal strain (the
//! issue's (a)–(f): Carslaw & Jaeger's slab, semi-infinite body and fin, Jaeger's moving band; the free block
//! and the bent strip), the heat balance and the paper's claims on punch-b40-heat. The bounds
//! are those of the tests that assert the same claims (`src/fe/conduction/tests.rs`,
//! `src/fe/elasticity/thermal.rs`, `tests/heat.rs`); docs/validation.md gives the reasons.

use super::cases::{fail, problem, push, Checks, Outcome};
use super::Bound;
use crate::basis::{ModeKind, Space};
use crate::conduction::closed_forms::{moving_band_case, moving_band_temperature};
use crate::conduction::reduced::{constant_gain, HeatOperators, ReducedModel};
use crate::conduction::{ConductionBody, ConductionSpec, EdgeCondition, EdgePiece, FaceConvection};
use crate::driver;
use crate::elasticity::{Constraints, Discretisation, ElasticBody};
use crate::geometry::{Block, EdgeShape, Point};
use crate::material::{film_coefficient, Analysis, Material, ThermalMaterial};
use crate::mesh::{Mesh, MeshBlock};
use faer::Mat;

/// Steel as the issue gives it: 50 W/(m·K), 460 J/(kg·K), 7800 kg/m³, 1.2e-5 1/K.
fn steel() -> ThermalMaterial {
    ThermalMaterial::from_engineering(50.0, 460.0, 7800.0, 1.2e-5)
}

/// A rectangle [0, w] × [0, h] cut into `u` × `v` elements (v graded by `v_lines` if given),
/// its edges named bottom, right, top, left.
fn rectangle(w: f64, h: f64, u: usize, v: Vec<f64>) -> Result<Mesh, String> {
    let block = MeshBlock {
        block: Block::new(
            [[0.0, 0.0], [w, 0.0], [w, h], [0.0, h]],
            [
                EdgeShape::Straight,
                EdgeShape::Straight,
                EdgeShape::Straight,
                EdgeShape::Straight,
            ],
        )
        .map_err(|e| e.to_string())?,
        u_lines: (0..=u).map(|i| i as f64 / u as f64).collect(),
        v_lines: v,
        material: 0,
        edge_names: [
            Some("bottom".into()),
            Some("right".into()),
            Some("top".into()),
            Some("left".into()),
        ],
    };
    Mesh::build(vec![block]).map_err(|e| e.to_string())
}

fn even(n: usize) -> Vec<f64> {
    (0..=n).map(|i| i as f64 / n as f64).collect()
}

fn pieces(mesh: &Mesh, name: &str) -> Vec<EdgePiece> {
    EdgePiece::named(mesh, name)
}

/// A body of steel on `mesh` at p = 8 with `edges` and `faces`, thickness `t` mm, in the
/// spaces of a run's heat ([`crate::conduction::spaces`]): the tensor-product space in the
/// elements along its top edge, where the cases' heat enters, the trunk space elsewhere.
fn body(
    mesh: &Mesh,
    t: f64,
    edges: Vec<(EdgePiece, EdgeCondition)>,
    faces: Option<FaceConvection>,
) -> Result<ConductionBody, String> {
    ConductionBody::new(
        mesh,
        &ConductionSpec {
            name: "block".into(),
            p: 8,
            space: Space::Trunk,
            tensor_elements: pieces(mesh, "top").iter().map(|p| p.element).collect(),
            thickness: t,
            materials: vec![Some(steel())],
            edges,
            faces,
            flow: None,
            inflow_temperature: 0.0,
        },
    )
    .map_err(|e| e.to_string())
}

/// The load of a flux `q` (mW/mm²) on every piece of edge `name`.
fn flux(body: &ConductionBody, name: &str, q: f64) -> Vec<f64> {
    let mut load = vec![0.0; body.n_full()];
    for piece in pieces(&body.mesh, name) {
        for (l, f) in load.iter_mut().zip(body.edge_flux_load(&piece, q)) {
            *l += f;
        }
    }
    load
}

/// (a) the stationary slab, (b) the semi-infinite body, (f) the fin, (e) the moving band.
pub fn conduction(checks: &mut Checks) -> Outcome {
    let case = "heat.conduction";
    let err = |e: String| fail(case, e);
    let k = steel().conductivity;
    // (a) A 60 × 60 mm block, base held at 20 °C, 40 mW/mm² (40 kW/m²) on top, insulated
    // sides: T = T₀ + q z / k exactly (linear fields are in the space).
    let mesh = rectangle(60.0, 60.0, 3, even(3)).map_err(err)?;
    let held = pieces(&mesh, "bottom")
        .into_iter()
        .map(|p| (p, EdgeCondition::Temperature(20.0)))
        .collect();
    let slab = body(&mesh, 10.0, held, None).map_err(err)?;
    let field = slab
        .stationary(&flux(&slab, "top", 40.0))
        .map_err(|e| err(e.to_string()))?;
    let top = slab.value_at(&field, [30.0, 60.0]).unwrap_or(f64::NAN);
    push(
        checks,
        "heat.slab",
        "slab under a flux, base held: top temperature (p = 8)",
        "°C",
        20.0 + 40.0 * 60.0 / k,
        "closed form: T₀ + q h / k",
        top,
        Bound::Relative(1e-8),
    );
    // (f) A plane-stress strip 200 × 20 mm, 2 mm thick, held at 100 °C at x = 0, faces
    // losing heat to 20 °C with h = 25 W/(m²·K): T − T∞ ∝ cosh(m(L − x)).
    let h = film_coefficient(25.0);
    let mesh = rectangle(200.0, 20.0, 10, even(1)).map_err(err)?;
    let held = pieces(&mesh, "left")
        .into_iter()
        .map(|p| (p, EdgeCondition::Temperature(100.0)))
        .collect();
    let faces = FaceConvection {
        coefficient: h,
        ambient: 20.0,
    };
    let fin = body(&mesh, 2.0, held, Some(faces)).map_err(err)?;
    let field = fin
        .stationary(&vec![0.0; fin.n_full()])
        .map_err(|e| err(e.to_string()))?;
    let m = (2.0 * h / (k * 2.0)).sqrt();
    let x = 150.0;
    push(
        checks,
        "heat.fin",
        "plate fin held at one end, faces convecting: temperature at x = 150 mm",
        "°C",
        20.0 + 80.0 * (m * (200.0 - x)).cosh() / (m * 200.0).cosh(),
        "closed form: fin (cosh)",
        fin.value_at(&field, [x, 10.0]).unwrap_or(f64::NAN),
        Bound::Relative(1e-3),
    );
    // (b) The surface of a 60 mm deep block under 40 mW/mm² from t = 0, by the reduced
    // model the runs use: 2q √(t/(π k ρc)) while the block is semi-infinite (√(a t) ≈ 3.7 mm
    // at 1 s).
    let depth = 60.0;
    let mut lines = vec![0.0];
    let mut d = 0.5;
    let mut from_top = vec![];
    while d < depth {
        from_top.push(d);
        d *= 2.0;
    }
    lines.extend(from_top.iter().rev().map(|l| 1.0 - l / depth));
    lines.push(1.0);
    let mesh = rectangle(10.0, depth, 1, lines).map_err(err)?;
    let held = pieces(&mesh, "bottom")
        .into_iter()
        .map(|p| (p, EdgeCondition::Temperature(20.0)))
        .collect();
    let deep = body(&mesh, 10.0, held, None).map_err(err)?;
    let load = deep.restrict(&flux(&deep, "top", 40.0));
    let inputs = Mat::from_fn(load.len(), 1, |i, _| load[i]);
    let (conductivity, capacity) = deep.free_operators(0, deep.n_free());
    let operators = HeatOperators {
        conductivity: &conductivity,
        capacity: &capacity,
        matrices: deep.matrices(),
        symmetric: true,
    };
    let shifts = [0.0, 0.1, 1.0, 3.0, 10.0, 30.0, 100.0];
    let model = ReducedModel::new(operators, inputs.as_ref(), &shifts, &[])
        .map_err(|e| err(e.to_string()))?;
    let modal = model.project(inputs.as_ref());
    let a: Vec<f64> = (0..model.len())
        .map(|j| constant_gain(model.rates[j], 1.0) * modal[(j, 0)])
        .collect();
    let base = deep.restrict(
        &deep
            .stationary(&vec![0.0; deep.n_full()])
            .map_err(|e| err(e.to_string()))?,
    );
    let field: Vec<f64> = base
        .iter()
        .zip(model.field(&a))
        .map(|(b, d)| b + d)
        .collect();
    let rise = deep
        .value_at(&deep.expand(&field), [5.0, depth])
        .unwrap_or(f64::NAN)
        - 20.0;
    let s = steel();
    push(
        checks,
        "heat.semi_infinite",
        "semi-infinite body under a constant flux: surface rise after 1 s (reduced model)",
        "K",
        2.0 * 40.0 * (1.0 / (std::f64::consts::PI * s.conductivity * s.heat_capacity)).sqrt(),
        "Carslaw & Jaeger §2.9: 2q √(t/(π k ρc))",
        rise,
        Bound::Relative(1e-2),
    );
    // (e) A band of 40 mW/mm² on steel flowing past at 2 m/s (Péclet number 360): the peak of
    // Jaeger's moving band, to the 3 %.
    let (q, half_width, speed) = (40.0, 5.0, 2000.0);
    let (band, field) = moving_band_case(8, speed, q, true).map_err(|e| err(e.to_string()))?;
    let peak = |f: &dyn Fn(f64) -> f64| {
        (0..=100)
            .map(|i| f(-half_width + 2.0 * half_width * i as f64 / 100.0))
            .fold(f64::NEG_INFINITY, f64::max)
    };
    push(
        checks,
        "heat.moving_band",
        "band source on a half-space moving at 2 m/s (Péclet 360): peak surface rise",
        "K",
        peak(&|x| {
            moving_band_temperature(x, q, half_width, speed, s.conductivity, s.diffusivity())
        }),
        "Jaeger (1942), Carslaw & Jaeger §10.7",
        peak(&|x| band.value_at(&field, [x, 0.0]).unwrap_or(f64::NAN)),
        Bound::Relative(3e-2),
    );
    Ok(())
}

/// A 60 × 8 mm steel strip, p = 6, held stress-free at the ends of its middle line.
fn strip(analysis: Analysis) -> Result<ElasticBody, String> {
    let mesh = rectangle(60.0, 8.0, 6, vec![0.0, 0.5, 1.0])?;
    let dofs = crate::dofs::DofMap::new(&mesh, 6);
    let left = mesh.vertex_at([0.0, 4.0]).ok_or("no vertex")?;
    let right = mesh.vertex_at([60.0, 4.0]).ok_or("no vertex")?;
    ElasticBody::new(
        "strip",
        mesh,
        vec![Material {
            young: 2.0e5,
            poisson: 0.3,
        }],
        analysis,
        Discretisation {
            p: 6,
            space: Space::TensorProduct,
        },
        &Constraints {
            prescribed: vec![],
            springs: vec![],
            fixed: vec![
                dofs.vertex_dof(left, 0),
                dofs.vertex_dof(left, 1),
                dofs.vertex_dof(right, 1),
            ],
        },
    )
    .map_err(|e| e.to_string())
}

/// The displacement at `at` of the strip under a temperature rise linear in x and z.
fn thermal_displacement(
    body: &ElasticBody,
    rise: impl Fn(Point) -> f64,
    at: Point,
) -> Result<[f64; 2], String> {
    let loads = body
        .thermal_loads(&[1.2e-5], &vec![body.basis.space; body.mesh.elements.len()])
        .map_err(|e| e.to_string())?;
    let coefficients = |element: usize| -> Vec<f64> {
        let vertices = body.mesh.elements[element].vertices;
        body.basis
            .modes
            .iter()
            .map(|m| match m.kind {
                ModeKind::Vertex(v) => rise(body.mesh.vertices[vertices[v]]),
                _ => 0.0,
            })
            .collect()
    };
    let load = body.thermal_load_vector(&loads, coefficients);
    let mut rhs = Mat::from_fn(load.len(), 1, |i, _| load[i]);
    body.solve_in_place(&mut rhs).map_err(|e| e.to_string())?;
    let u = body.recover_thermal(
        (0..load.len()).map(|i| rhs[(i, 0)]).collect(),
        &loads,
        coefficients,
    );
    body.values_at(&u, at)
        .map(|v| v.displacement)
        .ok_or_else(|| "outside the strip".into())
}

/// (c) the free block under a uniform rise, (d) the strip bent by a gradient.
pub fn thermal_strain(checks: &mut Checks) -> Outcome {
    let case = "heat.thermal_strain";
    for (name, analysis, free) in [
        (
            "plane_stress",
            Analysis::PlaneStress { thickness: 10.0 },
            1.2e-5,
        ),
        (
            "plane_strain",
            Analysis::PlaneStrain { thickness: 10.0 },
            1.3 * 1.2e-5,
        ),
    ] {
        let body = strip(analysis).map_err(|e| fail(case, e))?;
        let u = thermal_displacement(&body, |_| 50.0, [60.0, 4.0]).map_err(|e| fail(case, e))?;
        push(
            checks,
            format!("heat.free_expansion.{name}"),
            format!(
                "free strip heated by 50 K ({}): u_x at its end",
                name.replace('_', " ")
            ),
            "mm",
            free * 50.0 * 60.0,
            if name == "plane_stress" {
                "closed form: α ΔT L"
            } else {
                "closed form: (1 + ν) α ΔT L"
            },
            u[0],
            Bound::Relative(1e-10),
        );
        let u = thermal_displacement(&body, |x| 5.0 * (x[1] - 4.0), [30.0, 4.0])
            .map_err(|e| fail(case, e))?;
        push(
            checks,
            format!("heat.bending.{name}"),
            format!(
                "free strip, 5 K/mm through its thickness ({}): sag at mid-span",
                name.replace('_', " ")
            ),
            "mm",
            free * 5.0 * 30.0 * 30.0 / 2.0,
            "closed form: curvature α′ dT/dz",
            u[1],
            Bound::Relative(1e-3),
        );
    }
    Ok(())
}

/// The heat balance of the steady state and the paper's claims on punch-b40-heat.
pub fn punch(checks: &mut Checks) -> Outcome {
    let hot = problem("punch-b40-heat", &[])?;
    let cold = problem("punch-b40", &[])?;
    let (with, ..) = driver::steady_with_heat(&hot).map_err(|e| fail("punch-b40-heat", e))?;
    let (without, ..) = driver::steady(&cold).map_err(|e| fail("punch-b40", e))?;
    let peak = without
        .p_plus
        .iter()
        .chain(&without.p_minus)
        .fold(0.0f64, |m, p| m.max(*p));
    let apart = with
        .p_plus
        .iter()
        .zip(&without.p_plus)
        .chain(with.p_minus.iter().zip(&without.p_minus))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    push(
        checks,
        "heat.steady_pressure",
        "punch-b40-heat: steady p⁺, p⁻ with heat against without (largest difference / peak)",
        "",
        0.0,
        "paper §1, §4: the same distribution",
        apart / peak,
        Bound::Absolute(1e-2),
    );
    let ten = problem(
        "punch-b40-heat",
        &[(
            "beta = 3.9269908169872414e-8",
            "beta = 3.9269908169872414e-7",
        )],
    )?;
    let (tenfold, ..) = driver::steady_with_heat(&ten).map_err(|e| fail("punch-b40-heat", e))?;
    let apart = with
        .p_plus
        .iter()
        .zip(&tenfold.p_plus)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    push(
        checks,
        "heat.steady_beta",
        "punch-b40-heat: steady p⁺ at β̃ and 10 β̃ (largest difference / peak)",
        "",
        0.0,
        "paper §4: independent of β̃",
        apart / peak,
        Bound::Absolute(5e-3),
    );
    Ok(())
}
