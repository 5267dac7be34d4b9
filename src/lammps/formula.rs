//! A wall displacement u(t) of a scene (`expression::Expression`, evalexpr syntax) as a
//! LAMMPS equal-style formula of `time`, for a region's `move` variables, or why it has
//! none with the same value.
//!
//! Exact means the same IEEE operations in the same order: every node becomes one
//! parenthesised LAMMPS operation, so LAMMPS's precedence rules never regroup it, the
//! operands are evaluated as tamp evaluates them, and the functions are the C library's
//! in both codes (evalexpr's `math::sin` is Rust's `f64::sin`, LAMMPS's `sin` is
//! `sin()` of libm; `^` is `pow` in both). Translated: numbers, `t` (LAMMPS's `time`,
//! the step times Δt), `+ − × /`, unary minus, `^`, `math::` sin, cos, tan, asin,
//! acos, atan, atan2, exp, ln, sqrt, abs and pow, and a motion in stages:
//! the comparisons `< <= > >=` (true and false in evalexpr, 1 and 0 in LAMMPS) and
//! `if(c, a, b)` (LAMMPS's `ternary(c,a,b)`). Refused: everything else (`==`, `%`,
//! other functions and variables), and a division of two integer expressions, which
//! evalexpr truncates (`1/2` is 0) and LAMMPS does not.

use crate::decimal::g;
use evalexpr::{DefaultNumericTypes, Node, Operator, Value};

/// The LAMMPS names of the evalexpr functions translated one to one.
const FUNCTIONS: [(&str, &str); 13] = [
    ("math::sin", "sin"),
    ("math::cos", "cos"),
    ("math::tan", "tan"),
    ("math::asin", "asin"),
    ("math::acos", "acos"),
    ("math::atan", "atan"),
    ("math::atan2", "atan2"),
    ("math::exp", "exp"),
    ("math::ln", "ln"),
    ("math::sqrt", "sqrt"),
    ("math::abs", "abs"),
    ("math::pow", "pow"),
    ("if", "ternary"),
];

/// A translated subexpression: its LAMMPS text and whether evalexpr computes it in
/// integers.
struct Term {
    text: String,
    integer: bool,
}

/// The LAMMPS formula of an expression of `t`, or why there is none.
pub fn lammps_formula(tree: &Node<DefaultNumericTypes>) -> Result<String, String> {
    term(tree).map(|t| t.text)
}

fn term(node: &Node<DefaultNumericTypes>) -> Result<Term, String> {
    let children = node.children();
    let operands = || children.iter().map(term).collect::<Result<Vec<_>, _>>();
    let binary = |symbol: &str| -> Result<Term, String> {
        let args = operands()?;
        if args.len() != 2 {
            return Err(format!("'{symbol}' with {} operands", args.len()));
        }
        let integer = args.iter().all(|a| a.integer);
        if symbol == "/" && integer {
            return Err(
                "a division of two integers, which evalexpr truncates (1/2 is 0) and LAMMPS does not: write 1.0/2.0"
                    .into(),
            );
        }
        Ok(Term {
            text: format!("({}){symbol}({})", args[0].text, args[1].text),
            integer: integer && symbol != "^",
        })
    };
    match node.operator() {
        Operator::RootNode => {
            let mut args = operands()?;
            if args.len() != 1 {
                return Err("an expression that is not one value".into());
            }
            Ok(args.remove(0))
        }
        Operator::Const { value } => match value {
            // Bare, in the parentheses of the operation that takes it.
            Value::Float(x) => Ok(Term {
                text: g(*x),
                integer: false,
            }),
            Value::Int(i) => Ok(Term {
                text: i.to_string(),
                integer: true,
            }),
            other => Err(format!("the constant {other}, which is not a number")),
        },
        Operator::VariableIdentifierRead { identifier } if identifier == "t" => Ok(Term {
            text: "time".into(),
            integer: false,
        }),
        Operator::Add => binary("+"),
        Operator::Sub => binary("-"),
        Operator::Mul => binary("*"),
        Operator::Div => binary("/"),
        Operator::Exp => binary("^"),
        Operator::Lt => binary("<"),
        Operator::Leq => binary("<="),
        Operator::Gt => binary(">"),
        Operator::Geq => binary(">="),
        Operator::Neg => {
            let args = operands()?;
            match args.as_slice() {
                [a] => Ok(Term {
                    text: format!("-({})", a.text),
                    integer: a.integer,
                }),
                _ => Err("a negation of several operands".into()),
            }
        }
        Operator::FunctionIdentifier { identifier } => {
            let Some((_, name)) = FUNCTIONS.iter().find(|(f, _)| f == identifier) else {
                return Err(format!(
                    "the function {identifier}, which is not translated to LAMMPS"
                ));
            };
            // The argument is one node: a value, or a tuple of them, perhaps inside
            // the root node of its parentheses.
            let [first] = children else {
                return Err(format!("{identifier} without one argument list"));
            };
            let mut argument = first;
            while let (Operator::RootNode, [inner]) = (argument.operator(), argument.children()) {
                argument = inner;
            }
            let args = match argument.operator() {
                Operator::Tuple => argument
                    .children()
                    .iter()
                    .map(term)
                    .collect::<Result<Vec<_>, _>>()?,
                _ => vec![term(argument)?],
            };
            let list: Vec<String> = args.into_iter().map(|a| a.text).collect();
            Ok(Term {
                text: format!("{name}({})", list.join(",")),
                integer: false,
            })
        }
        other => Err(format!(
            "the operation '{other}', which is not translated to LAMMPS"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expression::Expression;

    fn formula(src: &str) -> Result<String, String> {
        lammps_formula(Expression::parse(src, &["t"]).unwrap().tree())
    }

    #[test]
    fn arithmetic_and_functions_become_parenthesised_lammps_operations() {
        assert_eq!(formula("0.02 * t").unwrap(), "(2e-2)*(time)");
        assert_eq!(
            formula("0.001 * math::sin(314.0 * t) - t^2.0").unwrap(),
            "((1e-3)*(sin((3.14e2)*(time))))-((time)^(2e0))"
        );
        // However evalexpr binds the minus, it stays one parenthesised operation.
        let negated = formula("-(t + 1.5) / 2").unwrap();
        assert!(
            negated.contains("-(")
                && negated.contains("(time)+(1.5e0)")
                && negated.contains("/(2)"),
            "{negated}"
        );
        assert_eq!(formula("math::atan2(t, 2.0)").unwrap(), "atan2(time,2e0)");
    }

    /// A motion in stages: evalexpr's `if` on a comparison is LAMMPS's `ternary` on
    /// the same comparison, which is 1 or 0 there.
    #[test]
    fn stages_become_ternaries_of_comparisons() {
        assert_eq!(
            formula("if(t < 0.5, 0.0, if(t <= 1.5, -0.1 * math::sin(2.0 * (t - 0.5)), 0.1))")
                .unwrap(),
            "ternary((time)<(5e-1),0e0,ternary((time)<=(1.5e0),(-(1e-1))*(sin((2e0)*((time)-(5e-1)))),1e-1))"
        );
        assert_eq!(
            formula("if(t >= 1.0, 1.0, 0.0)").unwrap(),
            "ternary((time)>=(1e0),1e0,0e0)"
        );
    }

    #[test]
    fn what_lammps_would_compute_differently_is_refused() {
        assert!(
            formula("t + 1/2")
                .unwrap_err()
                .contains("division of two integers")
        );
        assert!(formula("math::cbrt(t)").unwrap_err().contains("math::cbrt"));
        assert!(formula("if(t == 1.0, t, 0.0)").is_err());
        assert!(formula("t % 2.0").is_err());
    }
}
