//! Processes: multi-stage protocols run as a sequence of stage scenes that share the
//! particles' state (a LIGGGHTS input script with several `run` commands, as one
//! scene block).

pub mod cycle_replay;
pub mod die_compaction;
pub mod die_compaction_file;
pub mod die_compaction_run;
pub mod die_replay;
pub mod funnel;
pub mod press_cycle;
