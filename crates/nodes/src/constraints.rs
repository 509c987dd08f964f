//! Static constraints on ports' literal values (`Port::constraint`), checked before a graph
//! runs so that `locus check` reports them with the file position.

use locus_runtime::Value;

/// A radius: a positive, finite number.
pub(crate) fn positive_radius(value: &Value) -> Result<(), String> {
    match value {
        Value::Number(r) if r.is_finite() && *r > 0.0 => Ok(()),
        Value::Number(r) => Err(format!("the radius must be a positive number, got {r}")),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radii_are_positive_and_finite() {
        assert!(positive_radius(&Value::Number(0.5)).is_ok());
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(positive_radius(&Value::Number(bad)).is_err(), "{bad}");
        }
    }
}
