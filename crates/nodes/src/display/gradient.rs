//! Display › Colour › Gradient: a colour for each number from a gradient of grips.
//!
//! Grasshopper's Gradient is a canvas widget whose grips are edited with the mouse; a file
//! stores them in the component's `Gradient` chunk (each grip a factor from 0 to 1 and two
//! colours, the one left of it and the one right of it, which differ at a sharp step) with a
//! `Linear` flag. Here the grips are the `grips` setting, written as text (see [`Gradient::parse`])
//! and read from Grasshopper files by the importer.
//!
//! A parameter `t` is normalised to `u = (t − L0) / (L1 − L0)`. Below the first grip the colour
//! is the first grip's left colour, from the last grip on it is the last grip's right colour.
//! Between two grips the colour goes from the lower grip's right colour to the upper grip's left
//! colour, channel by channel (alpha, red, green, blue, as 0–255 numbers rounded to the nearest
//! whole number at the end): linearly when `linear` is set, otherwise along the smooth in/out
//! polynomial `f = s²(3 − 2s)` of the fraction `s` of the way. At a grip's own factor the colour
//! is its right colour. \[I\] Grasshopper does not document its non-linear interpolation;
//! smooth in/out between neighbouring grips is what Grasshopper 2 names its "smooth"
//! progression, and a gradient's colours at its grips are the same either way.

use std::sync::Arc;

use locus_kernel::Color;
use locus_runtime::{
    DataType, NodeConfig, NodeError, NodeRegistry, NodeType, Port, Prepared, Value, cast_value,
};

/// Id of [`gradient`].
pub const GRADIENT: &str = "display.gradient";

/// The grips when a node has no `grips` setting: black at 0 to white at 1.
pub const DEFAULT_GRIPS: &str = "0 #000000; 1 #FFFFFF";

/// The most grips a gradient may have (Grasshopper's editor shows a few dozen at most).
pub const MAX_GRIPS: usize = 10_000;

/// Registers the Gradient.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(gradient());
}

/// One grip: its factor, and the colours just left and right of it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grip {
    /// Where the grip sits, normally 0 to 1.
    pub factor: f64,
    /// The colour approached from below.
    pub left: Color,
    /// The colour at the grip and approached from above.
    pub right: Color,
}

/// A gradient: grips in increasing factor (equal factors keep their order).
#[derive(Clone, Debug, PartialEq)]
pub struct Gradient {
    grips: Vec<Grip>,
    linear: bool,
}

fn channels(c: Color) -> [f64; 4] {
    [c.a, c.r, c.g, c.b].map(f64::from)
}

impl Gradient {
    /// A gradient of these grips (sorted by factor, stably), or why not: no grips, too many,
    /// or a factor that is not a finite number.
    ///
    /// # Errors
    /// As above.
    pub fn new(mut grips: Vec<Grip>, linear: bool) -> Result<Self, String> {
        if grips.is_empty() {
            return Err("the gradient has no grips".into());
        }
        if grips.len() > MAX_GRIPS {
            return Err(format!(
                "the gradient has {} grips, more than {MAX_GRIPS}",
                grips.len()
            ));
        }
        if let Some(g) = grips.iter().find(|g| !g.factor.is_finite()) {
            return Err(format!(
                "a grip's factor must be a finite number, got {}",
                g.factor
            ));
        }
        grips.sort_by(|a, b| a.factor.total_cmp(&b.factor));
        Ok(Gradient { grips, linear })
    }

    /// Reads grips written as `FACTOR COLOUR` or `FACTOR LEFT/RIGHT`, separated by `;`, with
    /// colours as `#RRGGBB`, `#AARRGGBB`, `R,G,B` or `A,R,G,B`: for example
    /// `0 #FF0000; 0.5 #FFFF00/#00FF00; 1 0,0,255`.
    ///
    /// # Errors
    /// The first grip that does not read, or as [`Gradient::new`].
    pub fn parse(text: &str, linear: bool) -> Result<Self, String> {
        let colour = |s: &str| -> Result<Color, String> {
            match cast_value(&Value::Text(s.trim().to_owned()), DataType::Colour) {
                Ok(Value::Colour(c)) => Ok(c),
                _ => Err(format!(
                    "\"{}\" is not a colour (#RRGGBB, #AARRGGBB, R,G,B or A,R,G,B)",
                    s.trim()
                )),
            }
        };
        let mut grips = Vec::new();
        for (k, grip) in text.split(';').enumerate() {
            let grip = grip.trim();
            if grip.is_empty() {
                continue;
            }
            let (factor, colours) = grip
                .split_once(char::is_whitespace)
                .ok_or_else(|| format!("grip {k} (\"{grip}\") needs a factor and a colour"))?;
            let factor: f64 = factor
                .parse()
                .map_err(|_| format!("grip {k}: \"{factor}\" is not a number"))?;
            let (left, right) = match colours.split_once('/') {
                Some((l, r)) => (colour(l), colour(r)),
                None => (colour(colours), colour(colours)),
            };
            let err = |e: String| format!("grip {k}: {e}");
            grips.push(Grip {
                factor,
                left: left.map_err(err)?,
                right: right.map_err(err)?,
            });
        }
        Gradient::new(grips, linear)
    }

    /// The colour at a normalised parameter (NaN gives `None`).
    pub fn colour_at(&self, u: f64) -> Option<Color> {
        if u.is_nan() {
            return None;
        }
        // The last grip at or below u.
        let upper = self.grips.partition_point(|g| g.factor <= u);
        let Some(i) = upper.checked_sub(1) else {
            return Some(self.grips[0].left);
        };
        let Some(next) = self.grips.get(i + 1) else {
            return Some(self.grips[i].right);
        };
        let lower = &self.grips[i];
        let s = (u - lower.factor) / (next.factor - lower.factor);
        let f = if self.linear {
            s
        } else {
            s * s * (3.0 - 2.0 * s)
        };
        let (a, b) = (channels(lower.right), channels(next.left));
        let [ca, cr, cg, cb] = std::array::from_fn(|k| {
            // Between two 0–255 channels, so the rounded value fits a byte.
            (a[k] + f * (b[k] - a[k])).round().clamp(0.0, 255.0) as u8
        });
        Some(Color::rgba(cr, cg, cb, ca))
    }
}

fn prepare(config: &NodeConfig<'_>) -> Result<Prepared, NodeError> {
    let linear = match config.setting("linear") {
        Some(Value::Boolean(b)) => *b,
        None => true,
        Some(other) => {
            return Err(NodeError(format!(
                "the linear setting must be a Boolean, not a {}",
                other.data_type()
            )));
        }
    };
    let gradient = match config.setting("grips") {
        Some(Value::Text(t)) => Gradient::parse(t, linear),
        None => Gradient::parse(DEFAULT_GRIPS, linear),
        Some(other) => {
            return Err(NodeError(format!(
                "the grips setting must be a Text, not a {}",
                other.data_type()
            )));
        }
    };
    Ok(Arc::new(gradient.map_err(NodeError)?) as Prepared)
}

/// Gradient \[Gradient\]: the colour of a gradient at each parameter.
pub fn gradient() -> NodeType {
    NodeType::new(GRADIENT, "Gradient", "Gradient", "Display")
        .subcategory("Colour")
        .gh_guid("6da9f120-3ad0-4b6e-9fe0-f8cde3a649b7")
        .description(
            "Gives the colour of a gradient at each parameter t, normalised to u = (t − L0) / \
             (L1 − L0). The gradient is the grips setting: grips as FACTOR COLOUR, or FACTOR \
             LEFT/RIGHT for a sharp step, separated by semicolons (colours #RRGGBB, #AARRGGBB, \
             R,G,B or A,R,G,B), default black at 0 to white at 1. Below the first grip the \
             colour is its left colour, from the last grip on its right colour; between grips \
             the channels are interpolated linearly, or smoothly (s²(3 − 2s)) when linear is \
             false. Equal limits are an error for the item, as is a NaN parameter.",
        )
        .input(
            Port::new("Lower limit", "L0", DataType::Number)
                .default_value(0.0)
                .doc("The parameter at the gradient's 0; default 0."),
        )
        .input(
            Port::new("Upper limit", "L1", DataType::Number)
                .default_value(1.0)
                .doc("The parameter at the gradient's 1; default 1."),
        )
        .input(Port::new("Parameter", "t", DataType::Number).doc("The parameters to colour."))
        .output(Port::new("Colour", "C", DataType::Colour).doc("The colour at each parameter."))
        .setting(
            "grips",
            DataType::Text,
            Some(Value::Text(DEFAULT_GRIPS.to_owned())),
            "The grips, FACTOR COLOUR or FACTOR LEFT/RIGHT separated by semicolons; default \
             black at 0 to white at 1.",
        )
        .setting(
            "linear",
            DataType::Boolean,
            Some(Value::Boolean(true)),
            "Whether colours are interpolated linearly between grips (otherwise smoothly); \
             default true.",
        )
        .prepare(prepare)
        .solve(|s| {
            let gradient = s
                .prepared::<Gradient>()
                .ok_or_else(|| NodeError("internal: the gradient was not prepared".into()))?;
            let (l0, l1, t) = (*s.item::<f64>(0)?, *s.item::<f64>(1)?, *s.item::<f64>(2)?);
            if l0 == l1 {
                return Err(NodeError(format!(
                    "the lower and upper limits are both {l0}: the range is empty"
                )));
            }
            let u = (t - l0) / (l1 - l0);
            let colour = gradient.colour_at(u).ok_or_else(|| {
                NodeError(format!(
                    "the parameter is not a number ({t} in {l0} to {l1})"
                ))
            })?;
            s.set(0, colour);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, items};
    use locus_runtime::{DataTree, NodeCall};

    fn rgb(r: u8, g: u8, b: u8) -> Color {
        Color::rgb(r, g, b)
    }

    fn numbers(xs: &[f64]) -> DataTree {
        DataTree::from_list(xs.to_vec())
    }

    #[test]
    fn grips_read_sorted_with_steps() {
        let g = Gradient::parse("1 0,0,255; 0 #FF0000 ; 0.5 #FFFF00/#00FF00", true).unwrap();
        assert_eq!(g.grips.len(), 3);
        assert_eq!(g.grips[0].right, rgb(255, 0, 0));
        assert_eq!(g.grips[1].left, rgb(255, 255, 0));
        assert_eq!(g.grips[1].right, rgb(0, 255, 0));
        assert_eq!(g.grips[2].left, rgb(0, 0, 255));
        assert!(Gradient::parse("", true).unwrap_err().contains("no grips"));
        assert!(
            Gradient::parse("0", true)
                .unwrap_err()
                .contains("needs a factor")
        );
        assert!(
            Gradient::parse("x #FF0000", true)
                .unwrap_err()
                .contains("not a number")
        );
        assert!(
            Gradient::parse("0 #FF00", true)
                .unwrap_err()
                .contains("not a colour")
        );
        assert!(
            Gradient::parse("inf #FF0000", true)
                .unwrap_err()
                .contains("finite")
        );
    }

    #[test]
    fn colours_by_hand() {
        // Red at 0, a yellow/green step at 0.5, blue at 1.
        let g = Gradient::parse("0 #FF0000; 0.5 #FFFF00/#00FF00; 1 #0000FF", true).unwrap();
        assert_eq!(
            g.colour_at(-1.0),
            Some(rgb(255, 0, 0)),
            "below: the first grip"
        );
        assert_eq!(g.colour_at(0.0), Some(rgb(255, 0, 0)));
        // A quarter: half way from red to yellow, 127.5 rounds to 128.
        assert_eq!(g.colour_at(0.25), Some(rgb(255, 128, 0)));
        assert_eq!(
            g.colour_at(0.5),
            Some(rgb(0, 255, 0)),
            "at a step: its right colour"
        );
        assert_eq!(g.colour_at(0.75), Some(rgb(0, 128, 128)));
        assert_eq!(g.colour_at(1.0), Some(rgb(0, 0, 255)));
        assert_eq!(
            g.colour_at(7.0),
            Some(rgb(0, 0, 255)),
            "above: the last grip"
        );
        assert_eq!(g.colour_at(f64::NAN), None);
        // Smooth: the same at the grips and half way, eased between (s = 0.25 → f = 0.15625).
        let smooth = Gradient::parse("0 #000000; 1 #FFFFFF", false).unwrap();
        assert_eq!(smooth.colour_at(0.5), Some(rgb(128, 128, 128)));
        assert_eq!(smooth.colour_at(0.25), Some(rgb(40, 40, 40)));
        assert_eq!(smooth.colour_at(1.0), Some(rgb(255, 255, 255)));
    }

    #[test]
    fn alpha_is_interpolated_too() {
        let g = Gradient::parse("0 0,0,0,0; 1 255,0,0,0", true).unwrap();
        assert_eq!(g.colour_at(0.5), Some(Color::rgba(0, 0, 0, 128)));
    }

    #[test]
    fn the_node_normalises_by_its_limits() {
        let r = NodeCall::new(&gradient())
            .setting("grips", Value::Text("0 #000000; 1 #FFFFFF".into()))
            .input(numbers(&[10.0]))
            .input(numbers(&[20.0]))
            .input(numbers(&[10.0, 15.0, 20.0, 25.0]))
            .run();
        assert_clean(&r);
        assert_eq!(
            items::<Color>(&r.outputs[0]),
            vec![
                Some(rgb(0, 0, 0)),
                Some(rgb(128, 128, 128)),
                Some(rgb(255, 255, 255)),
                Some(rgb(255, 255, 255))
            ]
        );
        // Reversed limits run the gradient backwards.
        let r = NodeCall::new(&gradient())
            .input(numbers(&[1.0]))
            .input(numbers(&[0.0]))
            .input(numbers(&[0.0]))
            .run();
        assert_eq!(
            items::<Color>(&r.outputs[0]),
            vec![Some(rgb(255, 255, 255))]
        );
    }

    #[test]
    fn bad_input_is_reported() {
        let r = NodeCall::new(&gradient())
            .input(numbers(&[2.0]))
            .input(numbers(&[2.0]))
            .input(numbers(&[1.0]))
            .run();
        assert_error(&r, "range is empty");
        let r = NodeCall::new(&gradient())
            .input(numbers(&[0.0]))
            .input(numbers(&[1.0]))
            .input(numbers(&[f64::NAN]))
            .run();
        assert_error(&r, "not a number");
        let r = NodeCall::new(&gradient())
            .setting("grips", Value::Text("0 purple".into()))
            .input(numbers(&[0.0]))
            .input(numbers(&[1.0]))
            .input(numbers(&[0.5]))
            .run();
        assert_error(&r, "not a colour");
    }
}
