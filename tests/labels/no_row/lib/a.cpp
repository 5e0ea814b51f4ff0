double foo() { return 1; }  // eq:Foo
double bar() { return 2; }  // tab:Bar-I
