//! Display › Colour: Colour RGB (a colour from channels) and Split ARGB (the channels of a
//! colour).

use locus_kernel::Color;
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port};

/// Id of [`colour_rgb`].
pub const COLOUR_RGB: &str = "display.colour_rgb";
/// Id of [`split_argb`].
pub const SPLIT_ARGB: &str = "display.split_argb";

/// Registers Colour RGB and Split ARGB.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(colour_rgb());
    registry.register(split_argb());
}

/// A channel from a number: rounded, and an error outside 0 to 255 or for NaN.
fn channel(name: &str, x: f64) -> Result<u8, NodeError> {
    let r = x.round();
    if (0.0..=255.0).contains(&r) {
        Ok(r as u8)
    } else {
        Err(format!("{name} must be between 0 and 255, got {x}").into())
    }
}

fn channel_port(name: &str, nick: &str, default: f64, doc: &str) -> Port {
    Port::new(name, nick, DataType::Number)
        .default_value(default)
        .doc(doc)
}

/// Colour RGB \[RGB\]: a colour from alpha, red, green and blue.
pub fn colour_rgb() -> NodeType {
    NodeType::new(COLOUR_RGB, "Colour RGB", "RGB", "Display")
        .gh_guid("49d2e200-b34e-4e1c-82a3-07feb4cb9378")
        .subcategory("Colour")
        .description(
            "Creates a colour from alpha, red, green and blue channels, each 0 to 255 \
             (rounded to the nearest whole number). A channel outside 0 to 255 is an error.",
        )
        .input(channel_port(
            "Alpha",
            "A",
            255.0,
            "Alpha (opacity), 0 to 255; 255 is opaque.",
        ))
        .input(channel_port("Red", "R", 0.0, "Red, 0 to 255."))
        .input(channel_port("Green", "G", 0.0, "Green, 0 to 255."))
        .input(channel_port("Blue", "B", 0.0, "Blue, 0 to 255."))
        .output(Port::new("Colour", "C", DataType::Colour).doc("The colour."))
        .solve(|s| {
            let a = channel("alpha", *s.item::<f64>(0)?)?;
            let r = channel("red", *s.item::<f64>(1)?)?;
            let g = channel("green", *s.item::<f64>(2)?)?;
            let b = channel("blue", *s.item::<f64>(3)?)?;
            s.set(0, Color::rgba(r, g, b, a));
            Ok(())
        })
}

/// Split ARGB \[ARGB\]: the channels of a colour.
pub fn split_argb() -> NodeType {
    NodeType::new(SPLIT_ARGB, "Split ARGB", "ARGB", "Display")
        .gh_guid("350f7d03-a48f-4121-bcee-328cfe1ed9ef")
        .subcategory("Colour")
        .description("Splits a colour into its alpha, red, green and blue channels (0 to 255).")
        .input(Port::new("Colour", "C", DataType::Colour).doc("The colour to split."))
        .output(Port::new("Alpha", "A", DataType::Number).doc("Alpha, 0 to 255."))
        .output(Port::new("Red", "R", DataType::Number).doc("Red, 0 to 255."))
        .output(Port::new("Green", "G", DataType::Number).doc("Green, 0 to 255."))
        .output(Port::new("Blue", "B", DataType::Number).doc("Blue, 0 to 255."))
        .solve(|s| {
            let c = *s.item::<Color>(0)?;
            for (i, x) in [c.a, c.r, c.g, c.b].into_iter().enumerate() {
                s.set(i, f64::from(x));
            }
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, only};
    use locus_runtime::{DataTree, NodeCall, Value};

    fn n(x: f64) -> DataTree {
        DataTree::from_value(Value::Number(x))
    }

    #[test]
    fn rgb_and_back() {
        let r = NodeCall::new(&colour_rgb())
            .input(n(128.0))
            .input(n(255.0))
            .input(n(127.6))
            .input(n(0.0))
            .run();
        assert_clean(&r);
        let c = only::<Color>(&r, 0);
        assert_eq!(c, Color::rgba(255, 128, 0, 128));
        let r = NodeCall::new(&split_argb())
            .input(DataTree::from_value(Value::Colour(c)))
            .run();
        assert_eq!(
            (0..4).map(|i| only::<f64>(&r, i)).collect::<Vec<_>>(),
            vec![128.0, 255.0, 128.0, 0.0]
        );
    }

    #[test]
    fn channels_out_of_range_are_errors() {
        let r = NodeCall::new(&colour_rgb())
            .input(n(255.0))
            .input(n(300.0))
            .run();
        assert_error(&r, "red must be between 0 and 255");
        let r = NodeCall::new(&colour_rgb()).input(n(f64::NAN)).run();
        assert_error(&r, "alpha");
    }
}
