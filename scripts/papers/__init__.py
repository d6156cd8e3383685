"""scripts/reproduce-papers.py's parts: running the lesson steps (runs), what is measured on
a run (measures), the rows each paper's table states (rows), and the page's generated tables
(page)."""
