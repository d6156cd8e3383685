# panels tests
