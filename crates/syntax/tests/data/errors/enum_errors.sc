enum Empty {}
enum Missing { A B C }
enum Bad { A, 3, B }
enum Good { X, Y }
