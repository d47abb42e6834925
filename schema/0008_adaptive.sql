-- Adaptive campaigns (issue 30, docs/sweeps.md "adaptive"): every decision the planner took,
-- one row each, written in the same transaction as the job it adds. A decision is a function
-- of the campaign's finished results only (it is taken when no job of its series is pending or
-- running), so a campaign resumed at any point takes the same decisions again.
--   action 'add':  job_key was added (or, if it existed, linked) at width w, replica
--   action 'stop': the series needs no more jobs; reason says why (targets met, the budget of
--                  added jobs spent, or the series cannot be fitted)
-- k_err, beta_err: the fit's standard errors when the decision was taken; *_after: those the
-- design predicts with the added run (reports/next_width.h).
CREATE TABLE adaptive_decisions (
  campaign_id    INTEGER NOT NULL REFERENCES campaigns(id),
  series_key     TEXT    NOT NULL,
  seq            INTEGER NOT NULL,   -- 1, 2, ... per series
  action         TEXT    NOT NULL CHECK (action IN ('add', 'stop')),
  job_key        TEXT    REFERENCES jobs(key),
  w              REAL,
  replica        INTEGER,
  reason         TEXT    NOT NULL,
  k_err          REAL,
  beta_err       REAL,
  k_err_after    REAL,
  beta_err_after REAL,
  flowing_points INTEGER,
  created_at     TEXT    NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
  PRIMARY KEY (campaign_id, series_key, seq)
);
