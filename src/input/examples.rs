//! The built-in example problems: the files in `examples/`, compiled into the binary so that
//! `wearfem run punch-b40` works anywhere.

/// (name, problem file text) of every built-in example.
pub const EXAMPLES: &[(&str, &str)] = &[
    ("lame", include_str!("../../examples/lame.toml")),
    ("hertz", include_str!("../../examples/hertz.toml")),
    (
        "fretting-cylinder",
        include_str!("../../examples/fretting-cylinder.toml"),
    ),
    (
        "fretting-gross-slip",
        include_str!("../../examples/fretting-gross-slip.toml"),
    ),
    (
        "fretting-dissimilar",
        include_str!("../../examples/fretting-dissimilar.toml"),
    ),
    ("punch-a", include_str!("../../examples/punch-a.toml")),
    ("punch-b20", include_str!("../../examples/punch-b20.toml")),
    ("punch-b40", include_str!("../../examples/punch-b40.toml")),
    (
        "punch-b40-heat",
        include_str!("../../examples/punch-b40-heat.toml"),
    ),
    (
        "punch-b40-b1.2",
        include_str!("../../examples/punch-b40-b1.2.toml"),
    ),
    (
        "punch-b40-b0.8",
        include_str!("../../examples/punch-b40-b0.8.toml"),
    ),
    (
        "punch-b40-variant2",
        include_str!("../../examples/punch-b40-variant2.toml"),
    ),
    (
        "punch-b40-variant3",
        include_str!("../../examples/punch-b40-variant3.toml"),
    ),
    (
        "punch-b20-variant2",
        include_str!("../../examples/punch-b20-variant2.toml"),
    ),
    ("brake", include_str!("../../examples/brake.toml")),
    ("brake-heat", include_str!("../../examples/brake-heat.toml")),
    (
        "brake-drag-heat",
        include_str!("../../examples/brake-drag-heat.toml"),
    ),
    (
        "brake-independent",
        include_str!("../../examples/brake-independent.toml"),
    ),
    ("pin", include_str!("../../examples/pin.toml")),
    ("tribometer", include_str!("../../examples/tribometer.toml")),
    (
        "block-on-ring",
        include_str!("../../examples/block-on-ring.toml"),
    ),
    (
        "ball-on-flat",
        include_str!("../../examples/ball-on-flat.toml"),
    ),
    (
        "axisymmetric-punch",
        include_str!("../../examples/axisymmetric-punch.toml"),
    ),
    (
        "thrust-washer",
        include_str!("../../examples/thrust-washer.toml"),
    ),
    (
        "rotating-punch",
        include_str!("../../examples/rotating-punch.toml"),
    ),
];

/// The text of built-in example `name`.
pub fn example(name: &str) -> Option<&'static str> {
    EXAMPLES.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

/// The text of punch example `name` (any `punch-*` built-in) with `elements` elements under
/// the punch instead of 8: both punch blocks are cut into `elements` columns and the strip's
/// mesh lines between x = 1070 and 1130 mm are matched to them. None for other examples.
/// The studies of mesh refinement (docs/convergence.md, tests/refined.rs) use it.
pub fn refined_punch(name: &str, elements: usize) -> Option<String> {
    const STRIP: &str =
        "u = [0.0, 0.2, 0.35, 0.3875, 0.425, 0.4625, 0.5, 0.5375, 0.575, 0.6125, 0.65, 0.8, 1.0]";
    const PUNCH_BOTTOM: &str = "u = 8                          # x lines every 7.5 mm";
    const PUNCH_TOP: &str = "u = 8\nv = 4";
    let text = example(name)?;
    if elements == 0 || !(text.contains(STRIP) && text.contains(PUNCH_BOTTOM)) {
        return None;
    }
    let strip: Vec<String> = [0.0, 0.2]
        .into_iter()
        .chain((0..=elements).map(|i| 0.35 + 0.3 * i as f64 / elements as f64))
        .chain([0.8, 1.0])
        .map(|x| format!("{x:?}"))
        .collect();
    Some(
        text.replace(STRIP, &format!("u = [{}]", strip.join(", ")))
            .replace(PUNCH_BOTTOM, &format!("u = {elements}"))
            .replace(PUNCH_TOP, &format!("u = {elements}\nv = 4")),
    )
}
