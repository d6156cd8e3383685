# plots tests
