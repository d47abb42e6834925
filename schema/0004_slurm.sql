-- The Slurm executor. A submission is one sbatch call (one job array); it is recorded with
-- state 'submitting' and a unique job name BEFORE sbatch runs, and gets its Slurm id after, so
-- that a coordinator killed between the two finds the array again by name (or knows that it
-- was never submitted). Attempts gain their Slurm ids and the states Slurm can end them in.
-- attempts is rebuilt (SQLite cannot change a CHECK constraint in place); open_store runs
-- migrations with foreign keys off and checks them before committing.

CREATE TABLE slurm_submissions (
  id            INTEGER PRIMARY KEY,
  name          TEXT NOT NULL UNIQUE,     -- sbatch --job-name: beverloo-<random hex>
  state         TEXT NOT NULL CHECK (state IN ('submitting', 'submitted', 'never_submitted')),
  slurm_job_id  TEXT,                     -- the array's id, as sbatch --parsable printed it
  array_size    INTEGER NOT NULL,         -- tasks 0 .. array_size-1
  throttle      INTEGER,                  -- the %N of --array (NULL: none)
  script        TEXT NOT NULL,            -- slurm/<name>/job.sh, relative to the campaign directory
  sbatch_args   TEXT NOT NULL,            -- the full command line, as JSON array
  created_at    TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
  submitted_at  TEXT,
  message       TEXT
);

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
                                               'node_failure', 'out_of_memory', 'stalled')),
  message        TEXT,
  slurm_submission INTEGER REFERENCES slurm_submissions (id),
  slurm_array_task INTEGER,               -- the array index whose manifest line holds this attempt
  slurm_job_id   TEXT,                    -- '<array id>_<task>' once submitted
  slurm_state    TEXT,                    -- the last state Slurm reported (PENDING, RUNNING, COMPLETED, ...)
  slurm_restarts INTEGER,                 -- SLURM_RESTART_COUNT seen in the heartbeat (requeues)
  UNIQUE (job_key, attempt_no)
);
INSERT INTO attempts_new (id, job_key, attempt_no, token, executor, host, pid, state, started_at, heartbeat_at, ended_at,
                          exit_status, failure_class, message)
SELECT id, job_key, attempt_no, token, executor, host, pid, state, started_at, heartbeat_at, ended_at,
       exit_status, failure_class, message FROM attempts;
DROP TABLE attempts;
ALTER TABLE attempts_new RENAME TO attempts;
CREATE INDEX attempts_state ON attempts (state);
CREATE INDEX attempts_submission ON attempts (slurm_submission);
