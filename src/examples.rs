//! The built-in example problems: the files in `examples/`, compiled into the binary so that
//! `wearfem run punch-b40` works anywhere.

/// (name, problem file text) of every built-in example.
pub const EXAMPLES: &[(&str, &str)] = &[
    ("lame", include_str!("../examples/lame.toml")),
    ("punch-a", include_str!("../examples/punch-a.toml")),
    ("punch-b20", include_str!("../examples/punch-b20.toml")),
    ("punch-b40", include_str!("../examples/punch-b40.toml")),
    (
        "punch-b40-b1.2",
        include_str!("../examples/punch-b40-b1.2.toml"),
    ),
    (
        "punch-b40-b0.8",
        include_str!("../examples/punch-b40-b0.8.toml"),
    ),
    (
        "punch-b40-variant2",
        include_str!("../examples/punch-b40-variant2.toml"),
    ),
    (
        "punch-b40-variant3",
        include_str!("../examples/punch-b40-variant3.toml"),
    ),
    (
        "punch-b20-variant2",
        include_str!("../examples/punch-b20-variant2.toml"),
    ),
    ("brake", include_str!("../examples/brake.toml")),
    (
        "brake-independent",
        include_str!("../examples/brake-independent.toml"),
    ),
    ("pin", include_str!("../examples/pin.toml")),
];

/// The text of built-in example `name`.
pub fn example(name: &str) -> Option<&'static str> {
    EXAMPLES.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}
