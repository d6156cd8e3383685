# arena tests
