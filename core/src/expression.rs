//! Scalar expressions written in scene files: boundary displacements u(t) and
//! height-field surfaces z = f(x, y). Parsed once with `evalexpr` (a maintained
//! expression crate; writing a parser here would be one more thing to verify) and
//! checked by a trial evaluation so a typo is reported when the scene is loaded,
//! not in the middle of a run.
//!
//! Syntax: the usual arithmetic with `^` for powers and functions in the `math::`
//! namespace, e.g. `0.001 * math::sin(314.159 * t)` (there is no constant for π:
//! write the number). Integer literals stay integers, so `1/2` is 0: write `0.5` or
//! `1.0/2.0`. An expression whose trial value is an integer is rejected, but an
//! integer division inside a float expression (`t + 1/2`) cannot be detected.

use evalexpr::{
    ContextWithMutableVariables, DefaultNumericTypes, HashMapContext, Node, Value,
    build_operator_tree,
};

/// A parsed scalar expression of named free variables (t, or x and y), checked by a
/// trial evaluation.
#[derive(Clone, Debug)]
pub struct Expression {
    /// The text as written in the scene file.
    pub source: String,
    variables: Vec<&'static str>,
    tree: Node<DefaultNumericTypes>,
}

impl Expression {
    /// Parse `source` with the given free variables; the error says what is wrong.
    pub fn parse(source: &str, variables: &[&'static str]) -> Result<Self, String> {
        // evalexpr treats `a/b` of integers as integer division; forcing every
        // integer literal to a float would need a rewrite of the text, so instead the
        // trial evaluation below rejects expressions that yield an integer.
        let tree = build_operator_tree::<DefaultNumericTypes>(source)
            .map_err(|e| format!("cannot parse expression '{source}': {e}"))?;
        let e = Expression {
            source: source.to_string(),
            variables: variables.to_vec(),
            tree,
        };
        let probe = vec![0.5; variables.len()];
        let value = e.eval(&probe)?;
        if !value.is_finite() {
            return Err(format!(
                "expression '{source}' is not finite at {} = 0.5",
                variables.join(" = ")
            ));
        }
        Ok(e)
    }

    /// The parsed operator tree, for translating the expression into another code's
    /// formula language (`lammps::formula`).
    pub fn tree(&self) -> &Node<DefaultNumericTypes> {
        &self.tree
    }

    /// Evaluate with the variables set to `values`, in the order given to `parse`.
    pub fn eval(&self, values: &[f64]) -> Result<f64, String> {
        let mut context = HashMapContext::<DefaultNumericTypes>::new();
        for (name, &v) in self.variables.iter().zip(values) {
            context
                .set_value((*name).to_string(), Value::Float(v))
                .map_err(|e| format!("expression '{}': {e}", self.source))?;
        }
        match self.tree.eval_with_context(&context) {
            Ok(Value::Float(x)) => Ok(x),
            Ok(Value::Int(_)) => Err(format!(
                "expression '{}' evaluates to an integer; write numbers with a decimal point (1.0, not 1) so division is not integer division",
                self.source
            )),
            Ok(other) => Err(format!(
                "expression '{}' must evaluate to a number, got {other}",
                self.source
            )),
            Err(e) => Err(format!("expression '{}': {e}", self.source)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn evaluates_time_functions() {
        let e = Expression::parse("0.5 * t^2.0 + math::sin(t)", &["t"]).unwrap();
        let t = 0.3f64;
        assert!((e.eval(&[t]).unwrap() - (0.5 * t * t + t.sin())).abs() < 1e-15);
    }

    #[test]
    fn reports_bad_input() {
        assert!(Expression::parse("0.5 * ", &["t"]).is_err());
        assert!(Expression::parse("q * 2.0", &["t"]).is_err());
        let e = Expression::parse("1 / 2", &["t"]).unwrap_err();
        assert!(e.contains("integer"), "{e}");
    }
}
