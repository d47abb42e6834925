-- A failure class for a write that failed for want of room (core/disk_space.h): 'disk_full'.
-- It costs the job no retry, and the coordinator stops claiming jobs until someone makes room
-- (before, such attempts were 'io' and used up the jobs' retry budgets). attempts is rebuilt
-- (SQLite cannot change a CHECK constraint in place); open_store runs migrations with foreign
-- keys off and checks them before committing.

CREATE TABLE attempts_new (
  id             INTEGER PRIMARY KEY,
  job_key        TEXT NOT NULL REFERENCES jobs (key),
  attempt_no     INTEGER NOT NULL,
  token          TEXT NOT NULL UNIQUE,    -- fencing: a result is ingested only with its attempt's token
  executor       TEXT NOT NULL,           -- 'local' or 'slurm'
  host           TEXT,                    -- the coordinator's host (local: also the worker's)
  pid            INTEGER,                 -- local: the worker's pid
  state          TEXT NOT NULL CHECK (state IN ('running', 'succeeded', 'failed', 'lost', 'interrupted', 'cancelled')),
  started_at     TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
  heartbeat_at   TEXT,
  ended_at       TEXT,
  exit_status    INTEGER,                 -- worker exit code (or 128 + signal)
  failure_class  TEXT CHECK (failure_class IN ('invalid_parameters', 'blow_up', 'killed', 'timeout', 'io',
                                               'interrupted', 'lost', 'internal', 'cancelled', 'preempted',
                                               'node_failure', 'out_of_memory', 'stalled', 'disk_full')),
  message        TEXT,
  slurm_submission INTEGER REFERENCES slurm_submissions (id),
  slurm_array_task INTEGER,               -- the array index whose manifest line holds this attempt
  slurm_job_id   TEXT,                    -- '<array id>_<task>' once submitted
  slurm_state    TEXT,                    -- the last state Slurm reported (PENDING, RUNNING, COMPLETED, ...)
  slurm_restarts INTEGER,                 -- SLURM_RESTART_COUNT seen in the heartbeat (requeues)
  UNIQUE (job_key, attempt_no)
);
INSERT INTO attempts_new SELECT id, job_key, attempt_no, token, executor, host, pid, state, started_at, heartbeat_at,
                                ended_at, exit_status, failure_class, message, slurm_submission, slurm_array_task,
                                slurm_job_id, slurm_state, slurm_restarts FROM attempts;
DROP TABLE attempts;
ALTER TABLE attempts_new RENAME TO attempts;
CREATE INDEX attempts_state ON attempts (state);
CREATE INDEX attempts_submission ON attempts (slurm_submission);
