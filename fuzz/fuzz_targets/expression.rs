//! The Expression language: compiling any text never panics, and a program that compiles
//! evaluates (to a value or an error) without panicking on numbers, points, vectors, booleans
//! and texts, NaN and infinities included.
#![no_main]

use libfuzzer_sys::fuzz_target;
use locus_kernel::{Point3, Vector3};
use locus_nodes::expression::{Operand, Program};

const VARIABLES: [&str; 4] = ["x", "y", "P", "V"];

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    let Ok(program) = Program::compile(text, &VARIABLES) else {
        return;
    };
    let numbers = [0.0, 1.0, -2.5, f64::NAN, f64::INFINITY, 1e308, -0.0, 3.0];
    let x = numbers[usize::from(selector & 7)];
    let y = numbers[usize::from((selector >> 3) & 7)];
    let values = [
        if selector & 0x40 == 0 {
            Operand::Number(x)
        } else {
            Operand::Boolean(x > 0.0)
        },
        if selector & 0x80 == 0 {
            Operand::Number(y)
        } else {
            Operand::Text("a".into())
        },
        Operand::Point(Point3::new(x, 1.0, y)),
        Operand::Vector(Vector3::new(1.0, y, 0.0)),
    ];
    let _ = program.evaluate(|i| Ok(values[i].clone()));
});
