"""Pictures of colza results (issue 42): PNG plots of a result directory, read from the
run's own files (summary.json, curve.csv, load-<sigma>Pa/). Entry point: colza_plot.py."""
