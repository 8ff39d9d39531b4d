//! `--sweep KEY=FROM:TO:N`: one swept parameter of a stability map.

use std::str::FromStr;

use kreisel_analysis::{Parameter, Sweep};

/// A parsed `--sweep` argument: the parameter and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepArg {
    /// The parameter swept.
    pub parameter: Parameter,
    /// Its values.
    pub sweep: Sweep,
}

impl FromStr for SweepArg {
    type Err = String;

    /// `KEY=FROM:TO:N`, e.g. `spin=0:60:200`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let (key, range) = s
            .split_once('=')
            .ok_or_else(|| format!("{s:?} is not KEY=FROM:TO:N"))?;
        let parameter: Parameter = key.parse()?;
        let parts: Vec<&str> = range.split(':').collect();
        let [from, to, count] = parts[..] else {
            return Err(format!("{range:?} is not FROM:TO:N"));
        };
        let number = |text: &str, what: &str| {
            text.trim()
                .parse::<f64>()
                .map_err(|_| format!("{key}: {what} {text:?} is not a number"))
        };
        let count: usize = count
            .trim()
            .parse()
            .map_err(|_| format!("{key}: N {count:?} is not a whole number"))?;
        let sweep = Sweep::try_new(key, number(from, "FROM")?, number(to, "TO")?, count)
            .map_err(|e| e.to_string())?;
        Ok(Self { parameter, sweep })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweeps_parse_and_bad_ones_say_why() {
        let s: SweepArg = "spin=0:60:200".parse().unwrap();
        assert_eq!(
            (s.parameter, s.sweep.count, s.sweep.to),
            (Parameter::Spin, 200, 60.0)
        );
        for (text, message) in [
            ("spin", "\"spin\" is not KEY=FROM:TO:N"),
            (
                "omega=0:1:3",
                "unknown parameter \"omega\" (one of spin, tilt, com_offset, gravity, speed)",
            ),
            ("spin=0:1", "\"0:1\" is not FROM:TO:N"),
            ("spin=0:x:3", "spin: TO \"x\" is not a number"),
            ("spin=0:1:2.5", "spin: N \"2.5\" is not a whole number"),
            (
                "spin=0:1:1",
                "sweep spin: N = 1: a sweep needs at least 2 values",
            ),
        ] {
            assert_eq!(text.parse::<SweepArg>().unwrap_err(), message, "{text}");
        }
    }
}
