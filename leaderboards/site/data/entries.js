window.SYMBENCH_ENTRIES = {
 "hexa-climb-paper-v7__cosine__control-rotation__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--control-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__control-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.119 [0.115, 0.121]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.142 [0.138, 0.145]",
    "lower"
   ],
   [
    "equiv_err",
    "0.534 [0.487, 0.606]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__control-rotation__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--control-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__control-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.195 [0.189, 0.198]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.233 [0.225, 0.237]",
    "lower"
   ],
   [
    "equiv_err",
    "1.11 [1.02, 1.21]",
    "lower"
   ],
   [
    "invar_change",
    "1.01 [0.89, 1.15]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__control-rotation__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--control-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__control-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.459 [0.443, 0.467]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.548 [0.530, 0.557]",
    "lower"
   ],
   [
    "equiv_err",
    "1.38 [1.27, 1.54]",
    "lower"
   ],
   [
    "invar_change",
    "1.56 [1.49, 1.69]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__control-rotation__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--control-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__control-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0628 [0.0614, 0.0642]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0750 [0.0734, 0.0768]",
    "lower"
   ],
   [
    "equiv_err",
    "4.63 × 10⁻⁷ [3.94 × 10⁻⁷, 5.93 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__control-rotation__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--control-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__control-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0494 [0.0487, 0.0502]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0590 [0.0583, 0.0600]",
    "lower"
   ],
   [
    "equiv_err",
    "3.49 × 10⁻⁷ [3.09 × 10⁻⁷, 4.23 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__fraction-0.1__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--fraction-0-1",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__fraction-0.1__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.157 [0.156, 0.159]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.188 [0.186, 0.190]",
    "lower"
   ],
   [
    "equiv_err",
    "0.771 [0.721, 0.848]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "48 333 [45 000, 50 000]",
    ""
   ],
   [
    "epochs",
    "34.7 [32.0, 36.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__fraction-0.1__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--fraction-0-1",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__fraction-0.1__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.344 [0.330, 0.370]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.410 [0.393, 0.443]",
    "lower"
   ],
   [
    "equiv_err",
    "1.52 [1.46, 1.60]",
    "lower"
   ],
   [
    "invar_change",
    "1.18 [1.06, 1.29]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__fraction-0.1__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--fraction-0-1",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__fraction-0.1__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.596 [0.559, 0.656]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.711 [0.668, 0.781]",
    "lower"
   ],
   [
    "equiv_err",
    "1.53 [1.29, 1.71]",
    "lower"
   ],
   [
    "invar_change",
    "1.59 [1.47, 1.75]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "41 667 [35 000, 50 000]",
    ""
   ],
   [
    "epochs",
    "30.0 [25.0, 36.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 2",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__fraction-0.1__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--fraction-0-1",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__fraction-0.1__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0746 [0.0733, 0.0767]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0891 [0.0876, 0.0913]",
    "lower"
   ],
   [
    "equiv_err",
    "3.83 × 10⁻⁷ [3.53 × 10⁻⁷, 4.11 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__fraction-0.1__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--fraction-0-1",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__fraction-0.1__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0586 [0.0574, 0.0594]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0699 [0.0687, 0.0709]",
    "lower"
   ],
   [
    "equiv_err",
    "3.39 × 10⁻⁷ [3.23 × 10⁻⁷, 3.68 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "36.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__iid__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--iid",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__iid__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0749 [0.0746, 0.0753]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0918 [0.0782, 0.1020]",
    "higher"
   ],
   [
    "cl_score",
    "0.102 [0.087, 0.111]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0895 [0.0893, 0.0897]",
    "lower"
   ],
   [
    "equiv_err",
    "0.321 [0.305, 0.350]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "1.24 [1.08, 1.35]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0419 [0.0387, 0.0465]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "3.00",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__iid__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--iid",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0992 [0.0969, 0.1011]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0409 [0.0363, 0.0453]",
    "higher"
   ],
   [
    "cl_score",
    "0.0432 [0.0377, 0.0468]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.118 [0.116, 0.120]",
    "lower"
   ],
   [
    "equiv_err",
    "0.505 [0.430, 0.606]",
    "lower"
   ],
   [
    "invar_change",
    "0.557 [0.491, 0.685]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.669 [0.623, 0.717]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0509 [0.0450, 0.0551]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "3.00",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__iid__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--iid",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__iid__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.202 [0.185, 0.214]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0188 [0.0138, 0.0278]",
    "higher"
   ],
   [
    "cl_score",
    "0.0392 [0.0351, 0.0416]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.242 [0.222, 0.256]",
    "lower"
   ],
   [
    "equiv_err",
    "1.06 [0.91, 1.14]",
    "lower"
   ],
   [
    "invar_change",
    "1.41 [1.22, 1.57]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.630 [0.603, 0.661]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.109 [0.087, 0.119]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "3.00",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "iid",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__iid__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--iid",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__iid__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0505 [0.0490, 0.0520]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.521 [0.400, 0.675]",
    "higher"
   ],
   [
    "cl_score",
    "0.566 [0.429, 0.749]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0603 [0.0586, 0.0619]",
    "lower"
   ],
   [
    "equiv_err",
    "4.77 × 10⁻⁷ [4.42 × 10⁻⁷, 5.13 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.333 [0.250, 0.375]",
    "higher"
   ],
   [
    "cl_held_s",
    "5.77 [4.44, 7.54]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0201 [0.0174, 0.0232]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "3.00",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "iid",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__iid__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--iid",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0392 [0.0380, 0.0405]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.553 [0.431, 0.741]",
    "higher"
   ],
   [
    "cl_score",
    "0.590 [0.456, 0.810]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0468 [0.0455, 0.0482]",
    "lower"
   ],
   [
    "equiv_err",
    "4.64 × 10⁻⁷ [4.62 × 10⁻⁷, 4.66 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.292 [0.125, 0.625]",
    "higher"
   ],
   [
    "cl_held_s",
    "6.00 [4.70, 8.14]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0141 [0.0109, 0.0180]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "3.00",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__unseen-rotation__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--unseen-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__unseen-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.723 [0.705, 0.735]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0192 [0.0145, 0.0225]",
    "higher"
   ],
   [
    "cl_score",
    "0.0303 [0.0237, 0.0346]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.865 [0.844, 0.877]",
    "lower"
   ],
   [
    "equiv_err",
    "1.35 [1.11, 1.81]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.547 [0.509, 0.584]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0914 [0.0874, 0.0985]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--unseen-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.915 [0.880, 0.967]",
    "lower"
   ],
   [
    "cl_tracking",
    "-0.00274 [-0.00519, 0.00080]",
    "higher"
   ],
   [
    "cl_score",
    "-0.00538 [-0.01312, 0.00211]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.09 [1.05, 1.16]",
    "lower"
   ],
   [
    "equiv_err",
    "1.71 [1.62, 1.80]",
    "lower"
   ],
   [
    "invar_change",
    "0.951 [0.926, 0.970]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.200 [0.151, 0.250]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0963 [0.0882, 0.1051]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__unseen-rotation__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--unseen-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__unseen-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.685 [0.649, 0.728]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0291 [0.0217, 0.0371]",
    "higher"
   ],
   [
    "cl_score",
    "0.0502 [0.0399, 0.0621]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.819 [0.777, 0.868]",
    "lower"
   ],
   [
    "equiv_err",
    "1.52 [1.40, 1.76]",
    "lower"
   ],
   [
    "invar_change",
    "1.70 [1.60, 1.79]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.741 [0.637, 0.882]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0963 [0.0912, 0.1013]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 1",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__unseen-rotation__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--unseen-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__unseen-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0627 [0.0577, 0.0704]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.508 [0.450, 0.577]",
    "higher"
   ],
   [
    "cl_score",
    "0.594 [0.518, 0.662]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0749 [0.0688, 0.0843]",
    "lower"
   ],
   [
    "equiv_err",
    "4.48 × 10⁻⁷ [4.10 × 10⁻⁷, 4.86 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.333 [0.125, 0.500]",
    "higher"
   ],
   [
    "cl_held_s",
    "6.04 [5.30, 6.72]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0330 [0.0247, 0.0437]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-paper-v7__cosine__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-paper-v7.html#cosine--unseen-rotation",
  "dataset": "hexa-climb-paper-v7",
  "entry": "entries/hexa-climb-paper-v7__cosine__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0496 [0.0490, 0.0502]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.546 [0.463, 0.590]",
    "higher"
   ],
   [
    "cl_score",
    "0.617 [0.525, 0.681]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0594 [0.0585, 0.0600]",
    "lower"
   ],
   [
    "equiv_err",
    "3.60 × 10⁻⁷ [3.11 × 10⁻⁷, 3.91 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.375 [0.250, 0.500]",
    "higher"
   ],
   [
    "cl_held_s",
    "6.26 [5.37, 6.90]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0242 [0.0187, 0.0271]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "50 000",
    ""
   ],
   [
    "epochs",
    "20.0",
    ""
   ],
   [
    "stopped_by",
    "budget 3",
    ""
   ],
   [
    "seeds",
    "3",
    ""
   ]
  ],
  "protocol": "cosine",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-heading__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.127 [0.119, 0.133]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.162 [0.152, 0.171]",
    "lower"
   ],
   [
    "equiv_err",
    "0.786 [0.703, 0.870]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 000 [8 100, 9 900]",
    ""
   ],
   [
    "epochs",
    "23.4 [20.8, 25.8]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-heading__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.284 [0.263, 0.305]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.363 [0.337, 0.389]",
    "lower"
   ],
   [
    "equiv_err",
    "1.13 [0.97, 1.25]",
    "lower"
   ],
   [
    "invar_change",
    "1.38 [1.25, 1.55]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 000 [7 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "23.4 [18.2, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-heading",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-heading__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.257 [0.242, 0.270]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.328 [0.308, 0.346]",
    "lower"
   ],
   [
    "equiv_err",
    "1.08 [0.98, 1.22]",
    "lower"
   ],
   [
    "invar_change",
    "1.58 [1.48, 1.69]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "9 600 [8 800, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.0 [23.0, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-heading",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-heading__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0623 [0.0583, 0.0663]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0795 [0.0747, 0.0843]",
    "lower"
   ],
   [
    "equiv_err",
    "3.33 × 10⁻⁷ [3.01 × 10⁻⁷, 3.64 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-heading",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-heading__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0501 [0.0478, 0.0524]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0640 [0.0612, 0.0668]",
    "lower"
   ],
   [
    "equiv_err",
    "3.43 × 10⁻⁷ [3.12 × 10⁻⁷, 3.70 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-heading",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-rotation__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.217 [0.204, 0.231]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.277 [0.260, 0.294]",
    "lower"
   ],
   [
    "equiv_err",
    "0.818 [0.735, 0.908]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "4 700 [4 300, 5 000]",
    ""
   ],
   [
    "epochs",
    "32.0 [29.2, 34.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-rotation__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.516 [0.480, 0.556]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.658 [0.613, 0.707]",
    "lower"
   ],
   [
    "equiv_err",
    "1.33 [1.19, 1.45]",
    "lower"
   ],
   [
    "invar_change",
    "1.41 [1.34, 1.49]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "6 700 [5 000, 8 600]",
    ""
   ],
   [
    "epochs",
    "45.4 [33.8, 58.4]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-rotation__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.510 [0.464, 0.560]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.651 [0.595, 0.711]",
    "lower"
   ],
   [
    "equiv_err",
    "1.34 [1.30, 1.37]",
    "lower"
   ],
   [
    "invar_change",
    "1.56 [1.42, 1.71]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "4 700 [4 000, 5 400]",
    ""
   ],
   [
    "epochs",
    "31.8 [27.2, 36.4]",
    ""
   ],
   [
    "stopped_by",
    "patience 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-rotation__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0887 [0.0859, 0.0916]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.113 [0.110, 0.117]",
    "lower"
   ],
   [
    "equiv_err",
    "4.25 × 10⁻⁷ [3.86 × 10⁻⁷, 4.72 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "68.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__control-rotation__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--control-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__control-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0741 [0.0708, 0.0774]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0945 [0.0907, 0.0983]",
    "lower"
   ],
   [
    "equiv_err",
    "4.16 × 10⁻⁷ [3.79 × 10⁻⁷, 4.60 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "67.4 [66.2, 68.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "control-rotation",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.1__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.1__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.376 [0.355, 0.410]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.480 [0.452, 0.522]",
    "lower"
   ],
   [
    "equiv_err",
    "1.01 [0.94, 1.08]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "4 600 [4 000, 5 100]",
    ""
   ],
   [
    "epochs",
    "80.0 [69.6, 88.8]",
    ""
   ],
   [
    "stopped_by",
    "patience 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.1__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.1__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.674 [0.642, 0.706]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.860 [0.817, 0.904]",
    "lower"
   ],
   [
    "equiv_err",
    "1.48 [1.44, 1.50]",
    "lower"
   ],
   [
    "invar_change",
    "1.30 [1.22, 1.39]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "6 600 [4 200, 9 000]",
    ""
   ],
   [
    "epochs",
    "115 [73, 157]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.1__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.1__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.678 [0.642, 0.713]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.865 [0.821, 0.911]",
    "lower"
   ],
   [
    "equiv_err",
    "1.32 [1.04, 1.50]",
    "lower"
   ],
   [
    "invar_change",
    "1.46 [1.35, 1.56]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "6 200 [3 600, 8 800]",
    ""
   ],
   [
    "epochs",
    "108 [63, 154]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.1__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.1__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.153 [0.137, 0.165]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.196 [0.175, 0.209]",
    "lower"
   ],
   [
    "equiv_err",
    "3.70 × 10⁻⁷ [3.43 × 10⁻⁷, 3.96 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "166 [149, 175]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.1__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.1__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.139 [0.127, 0.150]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.177 [0.163, 0.191]",
    "lower"
   ],
   [
    "equiv_err",
    "3.20 × 10⁻⁷ [2.87 × 10⁻⁷, 3.61 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "8 100 [6 600, 9 600]",
    ""
   ],
   [
    "epochs",
    "142 [116, 168]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.1",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.25__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.25__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.226 [0.200, 0.255]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.289 [0.257, 0.325]",
    "lower"
   ],
   [
    "equiv_err",
    "0.813 [0.746, 0.862]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "4 800 [4 600, 5 000]",
    ""
   ],
   [
    "epochs",
    "32.8 [31.6, 34.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.25__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.25__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.517 [0.501, 0.533]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.659 [0.640, 0.679]",
    "lower"
   ],
   [
    "equiv_err",
    "1.48 [1.36, 1.58]",
    "lower"
   ],
   [
    "invar_change",
    "1.39 [1.28, 1.49]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "8 400 [7 100, 9 700]",
    ""
   ],
   [
    "epochs",
    "57.2 [48.4, 66.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.25__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.25__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.504 [0.462, 0.558]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.643 [0.593, 0.711]",
    "lower"
   ],
   [
    "equiv_err",
    "1.40 [1.32, 1.49]",
    "lower"
   ],
   [
    "invar_change",
    "1.56 [1.47, 1.66]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "7 500 [6 100, 8 800]",
    ""
   ],
   [
    "epochs",
    "51.2 [41.6, 60.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.25__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.25__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0887 [0.0819, 0.0953]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.113 [0.105, 0.121]",
    "lower"
   ],
   [
    "equiv_err",
    "3.94 × 10⁻⁷ [3.31 × 10⁻⁷, 4.68 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "68.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.25__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.25__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0745 [0.0688, 0.0807]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0950 [0.0877, 0.1029]",
    "lower"
   ],
   [
    "equiv_err",
    "3.56 × 10⁻⁷ [2.99 × 10⁻⁷, 4.27 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "68.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.25",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.5__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.5__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.149 [0.141, 0.157]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.191 [0.180, 0.201]",
    "lower"
   ],
   [
    "equiv_err",
    "0.839 [0.725, 0.952]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 600 [7 400, 9 800]",
    ""
   ],
   [
    "epochs",
    "29.4 [25.2, 33.4]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.5__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.5__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.365 [0.341, 0.388]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.465 [0.436, 0.494]",
    "lower"
   ],
   [
    "equiv_err",
    "1.24 [1.04, 1.47]",
    "lower"
   ],
   [
    "invar_change",
    "1.27 [1.23, 1.33]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "33.8 [33.4, 34.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.5__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.5__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.340 [0.288, 0.392]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.434 [0.369, 0.498]",
    "lower"
   ],
   [
    "equiv_err",
    "1.27 [1.07, 1.48]",
    "lower"
   ],
   [
    "invar_change",
    "1.51 [1.47, 1.58]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "8 800 [7 800, 9 700]",
    ""
   ],
   [
    "epochs",
    "30.2 [26.4, 33.4]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.5__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.5__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0684 [0.0643, 0.0727]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0873 [0.0823, 0.0924]",
    "lower"
   ],
   [
    "equiv_err",
    "3.31 × 10⁻⁷ [2.99 × 10⁻⁷, 3.58 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "34.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.5__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.5__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0539 [0.0501, 0.0574]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0688 [0.0639, 0.0730]",
    "lower"
   ],
   [
    "equiv_err",
    "3.46 × 10⁻⁷ [3.02 × 10⁻⁷, 3.89 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "34.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.5",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.75__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.75__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.120 [0.114, 0.129]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.154 [0.145, 0.165]",
    "lower"
   ],
   [
    "equiv_err",
    "0.760 [0.635, 0.882]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 800 [9 400, 10 000]",
    ""
   ],
   [
    "epochs",
    "22.6 [21.8, 23.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.75__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.75__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.271 [0.249, 0.294]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.345 [0.318, 0.375]",
    "lower"
   ],
   [
    "equiv_err",
    "1.14 [0.94, 1.37]",
    "lower"
   ],
   [
    "invar_change",
    "1.35 [1.28, 1.44]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "8 700 [7 600, 9 800]",
    ""
   ],
   [
    "epochs",
    "20.0 [17.4, 22.6]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.75__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.75__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.259 [0.223, 0.298]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.330 [0.285, 0.379]",
    "lower"
   ],
   [
    "equiv_err",
    "1.25 [1.06, 1.37]",
    "lower"
   ],
   [
    "invar_change",
    "1.57 [1.40, 1.75]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "22.8 [22.4, 23.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.75__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.75__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0603 [0.0562, 0.0644]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0770 [0.0720, 0.0820]",
    "lower"
   ],
   [
    "equiv_err",
    "3.58 × 10⁻⁷ [3.31 × 10⁻⁷, 3.87 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__fraction-0.75__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__fraction-0.75__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0487 [0.0456, 0.0518]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0621 [0.0583, 0.0659]",
    "lower"
   ],
   [
    "equiv_err",
    "3.46 × 10⁻⁷ [3.03 × 10⁻⁷, 3.82 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "fraction-0.75",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.105 [0.099, 0.111]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.447 [0.429, 0.469]",
    "higher"
   ],
   [
    "cl_score",
    "0.529 [0.492, 0.567]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.134 [0.127, 0.142]",
    "lower"
   ],
   [
    "equiv_err",
    "0.734 [0.688, 0.770]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.175 [0.125, 0.231]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.18 [1.11, 1.25]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0399 [0.0370, 0.0426]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__ffnn-leg__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn-leg__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.107 [0.101, 0.113]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.137 [0.129, 0.145]",
    "lower"
   ],
   [
    "equiv_err",
    "0.984 [0.908, 1.059]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "100 063",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn-leg (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__iid__ffnn__acc__jax": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn__acc__jax.html",
  "metrics": [
   [
    "rank",
    "5-7",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.228 [0.208, 0.253]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.325 [0.310, 0.338]",
    "higher"
   ],
   [
    "cl_score",
    "0.403 [0.392, 0.413]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "jax",
    ""
   ],
   [
    "nrmse",
    "0.291 [0.266, 0.323]",
    "lower"
   ],
   [
    "equiv_err",
    "1.07 [0.83, 1.31]",
    "lower"
   ],
   [
    "invar_change",
    "1.36 [1.29, 1.43]",
    "lower"
   ],
   [
    "cl_success",
    "0.0125 [0.0000, 0.0250]",
    "higher"
   ],
   [
    "cl_held_s",
    "0.958 [0.937, 0.977]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0552 [0.0512, 0.0593]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 500 [8 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "16.2 [15.0, 17.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn (acc, jax)"
 },
 "hexa-climb-small-v7__converge__iid__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5-7",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.224 [0.208, 0.242]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.327 [0.317, 0.338]",
    "higher"
   ],
   [
    "cl_score",
    "0.411 [0.394, 0.430]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.286 [0.266, 0.308]",
    "lower"
   ],
   [
    "equiv_err",
    "1.10 [0.93, 1.27]",
    "lower"
   ],
   [
    "invar_change",
    "1.41 [1.36, 1.46]",
    "lower"
   ],
   [
    "cl_success",
    "0.0125 [0.0000, 0.0250]",
    "higher"
   ],
   [
    "cl_held_s",
    "0.971 [0.941, 1.009]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0561 [0.0514, 0.0605]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 200 [7 800, 10 000]",
    ""
   ],
   [
    "epochs",
    "15.6 [13.2, 17.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__ffnn__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__ffnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.230 [0.213, 0.248]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.294 [0.273, 0.316]",
    "lower"
   ],
   [
    "equiv_err",
    "1.20 [0.98, 1.41]",
    "lower"
   ],
   [
    "invar_change",
    "1.37 [1.26, 1.49]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "100 115",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "ffnn (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__iid__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5-7",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.211 [0.205, 0.218]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.227 [0.190, 0.265]",
    "higher"
   ],
   [
    "cl_score",
    "0.305 [0.259, 0.349]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.269 [0.263, 0.278]",
    "lower"
   ],
   [
    "equiv_err",
    "0.980 [0.641, 1.324]",
    "lower"
   ],
   [
    "invar_change",
    "1.60 [1.44, 1.74]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.786 [0.708, 0.861]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0689 [0.0640, 0.0729]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__gnn__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__gnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.209 [0.194, 0.220]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.266 [0.248, 0.280]",
    "lower"
   ],
   [
    "equiv_err",
    "0.836 [0.695, 1.009]",
    "lower"
   ],
   [
    "invar_change",
    "1.56 [1.41, 1.76]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "99 381",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "gnn (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__iid__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0567 [0.0530, 0.0601]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.517 [0.486, 0.542]",
    "higher"
   ],
   [
    "cl_score",
    "0.591 [0.541, 0.637]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0724 [0.0678, 0.0766]",
    "lower"
   ],
   [
    "equiv_err",
    "4.20 × 10⁻⁷ [3.81 × 10⁻⁷, 4.59 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.244 [0.169, 0.294]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.29 [1.20, 1.36]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0345 [0.0312, 0.0383]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__sdgnn__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdgnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0517 [0.0491, 0.0543]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0660 [0.0628, 0.0693]",
    "lower"
   ],
   [
    "equiv_err",
    "4.44 × 10⁻⁷ [3.68 × 10⁻⁷, 5.40 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "100 299",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdgnn (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__iid__sdnn__acc__jax": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdnn__acc__jax.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0476 [0.0454, 0.0497]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.527 [0.486, 0.559]",
    "higher"
   ],
   [
    "cl_score",
    "0.599 [0.539, 0.646]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "jax",
    ""
   ],
   [
    "nrmse",
    "0.0608 [0.0580, 0.0634]",
    "lower"
   ],
   [
    "equiv_err",
    "3.33 × 10⁻⁷ [3.00 × 10⁻⁷, 3.73 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.244 [0.163, 0.319]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.30 [1.20, 1.38]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0343 [0.0317, 0.0368]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdnn (acc, jax)"
 },
 "hexa-climb-small-v7__converge__iid__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0458 [0.0431, 0.0487]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.559 [0.533, 0.585]",
    "higher"
   ],
   [
    "cl_score",
    "0.648 [0.613, 0.681]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0585 [0.0551, 0.0620]",
    "lower"
   ],
   [
    "equiv_err",
    "3.91 × 10⁻⁷ [3.54 × 10⁻⁷, 4.44 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.325 [0.269, 0.381]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.38 [1.32, 1.44]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0363 [0.0330, 0.0395]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__iid__sdnn__acc__torch__matched-100000": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__iid__sdnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0479 [0.0456, 0.0506]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0611 [0.0583, 0.0645]",
    "lower"
   ],
   [
    "equiv_err",
    "4.04 × 10⁻⁷ [3.66 × 10⁻⁷, 4.43 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "99 810",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "iid",
  "title": "sdnn (acc, torch), matched at 100 000 parameters"
 },
 "hexa-climb-small-v7__converge__unseen-heading__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.136 [0.131, 0.140]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.173 [0.167, 0.177]",
    "lower"
   ],
   [
    "equiv_err",
    "0.765 [0.707, 0.850]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-heading__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.485 [0.461, 0.503]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.618 [0.588, 0.641]",
    "lower"
   ],
   [
    "equiv_err",
    "1.25 [1.17, 1.29]",
    "lower"
   ],
   [
    "invar_change",
    "1.44 [1.37, 1.51]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "8 600 [6 600, 10 000]",
    ""
   ],
   [
    "epochs",
    "22.4 [17.2, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-heading__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.484 [0.460, 0.502]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.617 [0.587, 0.637]",
    "lower"
   ],
   [
    "equiv_err",
    "1.19 [1.14, 1.23]",
    "lower"
   ],
   [
    "invar_change",
    "1.71 [1.60, 1.84]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "9 800 [9 400, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.4 [24.2, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-heading__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0617 [0.0601, 0.0634]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0787 [0.0766, 0.0808]",
    "lower"
   ],
   [
    "equiv_err",
    "2.96 × 10⁻⁷ [2.83 × 10⁻⁷, 3.12 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-heading__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-heading",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0513 [0.0501, 0.0525]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0654 [0.0639, 0.0668]",
    "lower"
   ],
   [
    "equiv_err",
    "3.25 × 10⁻⁷ [3.00 × 10⁻⁷, 3.49 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-heading",
  "title": "sdnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-rotation__ffnn-leg__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.833 [0.803, 0.858]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0966 [0.0866, 0.1060]",
    "higher"
   ],
   [
    "cl_score",
    "0.161 [0.144, 0.175]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.07 [1.02, 1.10]",
    "lower"
   ],
   [
    "equiv_err",
    "1.68 [1.60, 1.75]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.533 [0.502, 0.556]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0988 [0.0955, 0.1013]",
    "lower"
   ],
   [
    "parameters",
    "172 306",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 000 [6 400, 9 600]",
    ""
   ],
   [
    "epochs",
    "54.4 [43.4, 65.4]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.995 [0.971, 1.019]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0465 [0.0421, 0.0513]",
    "higher"
   ],
   [
    "cl_score",
    "0.0855 [0.0742, 0.0995]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.27 [1.24, 1.31]",
    "lower"
   ],
   [
    "equiv_err",
    "1.70 [1.64, 1.73]",
    "lower"
   ],
   [
    "invar_change",
    "1.30 [1.24, 1.39]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.400 [0.380, 0.423]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.101 [0.098, 0.105]",
    "lower"
   ],
   [
    "parameters",
    "157 970",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "7 800 [6 100, 9 500]",
    ""
   ],
   [
    "epochs",
    "53.2 [41.6, 64.8]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-rotation__gnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.529 [0.512, 0.546]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.135 [0.118, 0.156]",
    "higher"
   ],
   [
    "cl_score",
    "0.217 [0.185, 0.263]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.677 [0.653, 0.701]",
    "lower"
   ],
   [
    "equiv_err",
    "1.37 [1.28, 1.47]",
    "lower"
   ],
   [
    "invar_change",
    "1.44 [1.34, 1.52]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.631 [0.573, 0.710]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0861 [0.0807, 0.0913]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.009",
    ""
   ],
   [
    "steps",
    "8 700 [7 300, 9 800]",
    ""
   ],
   [
    "epochs",
    "59.4 [49.8, 66.8]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "gnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-rotation__sdgnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0919 [0.0882, 0.0953]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.482 [0.467, 0.491]",
    "higher"
   ],
   [
    "cl_score",
    "0.560 [0.535, 0.576]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.118 [0.113, 0.122]",
    "lower"
   ],
   [
    "equiv_err",
    "3.94 × 10⁻⁷ [3.66 × 10⁻⁷, 4.14 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.225 [0.188, 0.250]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.23 [1.19, 1.26]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0383 [0.0357, 0.0408]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "68.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "hexa-climb-small-v7__converge__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/hexa__hexa-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "hexa-climb-small-v7",
  "entry": "entries/hexa-climb-small-v7__converge__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0762 [0.0726, 0.0793]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.510 [0.477, 0.546]",
    "higher"
   ],
   [
    "cl_score",
    "0.593 [0.545, 0.645]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0975 [0.0926, 0.1017]",
    "lower"
   ],
   [
    "equiv_err",
    "4.02 × 10⁻⁷ [3.40 × 10⁻⁷, 4.66 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.244 [0.181, 0.294]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.29 [1.20, 1.38]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0370 [0.0342, 0.0399]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0135",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "64.6 [57.8, 68.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "hexa",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-heading__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.179 [0.173, 0.189]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.141 [0.136, 0.148]",
    "lower"
   ],
   [
    "equiv_err",
    "0.392 [0.341, 0.444]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-heading__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.408 [0.388, 0.429]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.321 [0.305, 0.337]",
    "lower"
   ],
   [
    "equiv_err",
    "1.02 [0.90, 1.16]",
    "lower"
   ],
   [
    "invar_change",
    "1.23 [1.17, 1.28]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 700 [9 300, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.2 [24.0, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-heading",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-heading__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.569 [0.519, 0.640]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.447 [0.408, 0.503]",
    "lower"
   ],
   [
    "equiv_err",
    "1.21 [1.02, 1.38]",
    "lower"
   ],
   [
    "invar_change",
    "1.57 [1.48, 1.67]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-heading",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-heading__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.157 [0.153, 0.161]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.124 [0.120, 0.127]",
    "lower"
   ],
   [
    "equiv_err",
    "3.10 × 10⁻⁷ [2.85 × 10⁻⁷, 3.34 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-heading",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-heading__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.127 [0.123, 0.131]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0994 [0.0962, 0.1028]",
    "lower"
   ],
   [
    "equiv_err",
    "2.51 × 10⁻⁷ [2.29 × 10⁻⁷, 2.74 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-heading",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-rotation__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.180 [0.173, 0.191]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.141 [0.135, 0.151]",
    "lower"
   ],
   [
    "equiv_err",
    "0.336 [0.311, 0.362]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "27.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-rotation__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.416 [0.398, 0.438]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.327 [0.314, 0.344]",
    "lower"
   ],
   [
    "equiv_err",
    "1.03 [0.97, 1.12]",
    "lower"
   ],
   [
    "invar_change",
    "1.29 [1.21, 1.37]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.6 [22.8, 27.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-rotation",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-rotation__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.641 [0.570, 0.730]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.504 [0.447, 0.575]",
    "lower"
   ],
   [
    "equiv_err",
    "1.34 [1.12, 1.52]",
    "lower"
   ],
   [
    "invar_change",
    "1.52 [1.41, 1.65]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "26.6 [25.8, 27.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-rotation",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-rotation__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.158 [0.151, 0.165]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.124 [0.119, 0.130]",
    "lower"
   ],
   [
    "equiv_err",
    "3.00 × 10⁻⁷ [2.80 × 10⁻⁷, 3.22 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "26.6 [25.8, 27.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__control-rotation__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--control-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__control-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.129 [0.127, 0.132]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.102 [0.099, 0.104]",
    "lower"
   ],
   [
    "equiv_err",
    "2.95 × 10⁻⁷ [2.53 × 10⁻⁷, 3.34 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "27.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "control-rotation",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.1__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.1__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.491 [0.456, 0.524]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.386 [0.356, 0.412]",
    "lower"
   ],
   [
    "equiv_err",
    "0.639 [0.595, 0.682]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "175",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.1__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.1__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.07 [0.99, 1.15]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.842 [0.778, 0.906]",
    "lower"
   ],
   [
    "equiv_err",
    "1.22 [1.15, 1.29]",
    "lower"
   ],
   [
    "invar_change",
    "1.24 [1.17, 1.30]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "166 [149, 175]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.1__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.1__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.19 [1.15, 1.23]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.935 [0.910, 0.962]",
    "lower"
   ],
   [
    "equiv_err",
    "1.62 [1.52, 1.72]",
    "lower"
   ],
   [
    "invar_change",
    "1.62 [1.51, 1.73]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "4 900 [3 500, 7 500]",
    ""
   ],
   [
    "epochs",
    "85.6 [61.0, 131.2]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.1__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.1__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.300 [0.283, 0.315]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.236 [0.223, 0.247]",
    "lower"
   ],
   [
    "equiv_err",
    "3.98 × 10⁻⁷ [3.54 × 10⁻⁷, 4.31 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 200 [8 500, 9 900]",
    ""
   ],
   [
    "epochs",
    "161 [149, 173]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.1__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.1__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.286 [0.274, 0.296]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.224 [0.216, 0.233]",
    "lower"
   ],
   [
    "equiv_err",
    "2.94 × 10⁻⁷ [2.52 × 10⁻⁷, 3.32 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "175",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.1",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.25__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.25__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.283 [0.262, 0.308]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.222 [0.205, 0.242]",
    "lower"
   ],
   [
    "equiv_err",
    "0.489 [0.435, 0.532]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 400 [8 200, 10 000]",
    ""
   ],
   [
    "epochs",
    "64.0 [56.0, 68.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.25__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.25__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.750 [0.689, 0.812]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.589 [0.542, 0.639]",
    "lower"
   ],
   [
    "equiv_err",
    "1.08 [1.03, 1.13]",
    "lower"
   ],
   [
    "invar_change",
    "1.37 [1.26, 1.47]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "7 100 [4 900, 9 200]",
    ""
   ],
   [
    "epochs",
    "48.6 [33.6, 63.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.25__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.25__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.03 [1.02, 1.05]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.810 [0.796, 0.824]",
    "lower"
   ],
   [
    "equiv_err",
    "1.38 [1.25, 1.49]",
    "lower"
   ],
   [
    "invar_change",
    "1.50 [1.44, 1.57]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "7 300 [5 800, 8 800]",
    ""
   ],
   [
    "epochs",
    "49.6 [39.2, 60.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.25__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.25__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.201 [0.194, 0.208]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.158 [0.152, 0.163]",
    "lower"
   ],
   [
    "equiv_err",
    "3.63 × 10⁻⁷ [2.98 × 10⁻⁷, 4.30 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "68.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.25__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.25__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.180 [0.174, 0.186]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.142 [0.136, 0.147]",
    "lower"
   ],
   [
    "equiv_err",
    "2.43 × 10⁻⁷ [2.22 × 10⁻⁷, 2.64 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "68.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.25",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.5__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.5__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.204 [0.199, 0.207]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.160 [0.155, 0.163]",
    "lower"
   ],
   [
    "equiv_err",
    "0.371 [0.322, 0.451]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "34.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.5__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.5__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.502 [0.460, 0.552]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.394 [0.362, 0.433]",
    "lower"
   ],
   [
    "equiv_err",
    "1.11 [1.05, 1.16]",
    "lower"
   ],
   [
    "invar_change",
    "1.32 [1.24, 1.42]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 400 [8 200, 10 000]",
    ""
   ],
   [
    "epochs",
    "32.0 [28.0, 34.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.5__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.5__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.812 [0.723, 0.908]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.638 [0.567, 0.717]",
    "lower"
   ],
   [
    "equiv_err",
    "1.24 [1.02, 1.46]",
    "lower"
   ],
   [
    "invar_change",
    "1.48 [1.41, 1.55]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "8 800 [6 400, 10 000]",
    ""
   ],
   [
    "epochs",
    "29.8 [21.4, 34.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.5__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.5__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.166 [0.157, 0.174]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.130 [0.123, 0.137]",
    "lower"
   ],
   [
    "equiv_err",
    "3.35 × 10⁻⁷ [2.98 × 10⁻⁷, 3.66 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "34.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.5__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.5__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.138 [0.132, 0.145]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.109 [0.103, 0.114]",
    "lower"
   ],
   [
    "equiv_err",
    "2.55 × 10⁻⁷ [2.29 × 10⁻⁷, 2.79 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "34.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.5",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.75__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.75__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.176 [0.172, 0.183]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.138 [0.135, 0.144]",
    "lower"
   ],
   [
    "equiv_err",
    "0.426 [0.317, 0.590]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.75__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.75__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.391 [0.374, 0.418]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.308 [0.293, 0.329]",
    "lower"
   ],
   [
    "equiv_err",
    "1.03 [0.86, 1.19]",
    "lower"
   ],
   [
    "invar_change",
    "1.30 [1.26, 1.34]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 400 [8 200, 10 000]",
    ""
   ],
   [
    "epochs",
    "21.6 [18.8, 23.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.75__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.75__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.538 [0.513, 0.578]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.423 [0.402, 0.455]",
    "lower"
   ],
   [
    "equiv_err",
    "1.12 [0.96, 1.26]",
    "lower"
   ],
   [
    "invar_change",
    "1.59 [1.43, 1.72]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.75__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.75__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.155 [0.148, 0.162]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.122 [0.116, 0.128]",
    "lower"
   ],
   [
    "equiv_err",
    "3.08 × 10⁻⁷ [2.81 × 10⁻⁷, 3.34 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__fraction-0.75__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__fraction-0.75__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.123 [0.117, 0.128]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0965 [0.0913, 0.1004]",
    "lower"
   ],
   [
    "equiv_err",
    "2.44 × 10⁻⁷ [2.22 × 10⁻⁷, 2.66 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "fraction-0.75",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__iid__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.160 [0.155, 0.168]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.366 [0.355, 0.375]",
    "higher"
   ],
   [
    "cl_score",
    "0.387 [0.374, 0.397]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.126 [0.121, 0.132]",
    "lower"
   ],
   [
    "equiv_err",
    "0.326 [0.289, 0.364]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.887 [0.863, 0.908]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0300 [0.0291, 0.0308]",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__iid__ffnn-leg__acc__torch__matched-100000": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__ffnn-leg__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.165 [0.160, 0.172]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.130 [0.125, 0.135]",
    "lower"
   ],
   [
    "equiv_err",
    "0.330 [0.292, 0.388]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "100 002",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "ffnn-leg (acc, torch), matched at 100 000 parameters"
 },
 "magneto-climb-small-v7__converge__iid__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.337 [0.316, 0.366]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.282 [0.263, 0.300]",
    "higher"
   ],
   [
    "cl_score",
    "0.338 [0.315, 0.360]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.265 [0.249, 0.288]",
    "lower"
   ],
   [
    "equiv_err",
    "0.982 [0.875, 1.095]",
    "lower"
   ],
   [
    "invar_change",
    "1.30 [1.24, 1.34]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.799 [0.764, 0.835]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0503 [0.0474, 0.0531]",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__iid__ffnn__acc__torch__matched-100000": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__ffnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.341 [0.320, 0.367]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.268 [0.252, 0.289]",
    "lower"
   ],
   [
    "equiv_err",
    "1.00 [0.97, 1.05]",
    "lower"
   ],
   [
    "invar_change",
    "1.26 [1.22, 1.30]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "99 847",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "ffnn (acc, torch), matched at 100 000 parameters"
 },
 "magneto-climb-small-v7__converge__iid__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.455 [0.430, 0.472]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.130 [0.121, 0.139]",
    "higher"
   ],
   [
    "cl_score",
    "0.177 [0.164, 0.188]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.357 [0.339, 0.370]",
    "lower"
   ],
   [
    "equiv_err",
    "0.973 [0.866, 1.107]",
    "lower"
   ],
   [
    "invar_change",
    "1.46 [1.38, 1.56]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.514 [0.495, 0.532]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0714 [0.0686, 0.0751]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__iid__gnn__acc__torch__matched-100000": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__gnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.463 [0.439, 0.496]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.364 [0.346, 0.390]",
    "lower"
   ],
   [
    "equiv_err",
    "0.974 [0.814, 1.134]",
    "lower"
   ],
   [
    "invar_change",
    "1.40 [1.27, 1.55]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "99 381",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "gnn (acc, torch), matched at 100 000 parameters"
 },
 "magneto-climb-small-v7__converge__iid__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.150 [0.145, 0.153]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.385 [0.379, 0.392]",
    "higher"
   ],
   [
    "cl_score",
    "0.403 [0.395, 0.410]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.118 [0.113, 0.120]",
    "lower"
   ],
   [
    "equiv_err",
    "4.09 × 10⁻⁷ [3.62 × 10⁻⁷, 4.56 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.915 [0.898, 0.932]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0278 [0.0267, 0.0289]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__iid__sdgnn__acc__torch__matched-100000": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__sdgnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.139 [0.133, 0.145]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.109 [0.104, 0.114]",
    "lower"
   ],
   [
    "equiv_err",
    "2.74 × 10⁻⁷ [2.71 × 10⁻⁷, 2.77 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "100 299",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "sdgnn (acc, torch), matched at 100 000 parameters"
 },
 "magneto-climb-small-v7__converge__iid__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.114 [0.109, 0.119]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.405 [0.396, 0.413]",
    "higher"
   ],
   [
    "cl_score",
    "0.418 [0.408, 0.427]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0897 [0.0851, 0.0937]",
    "lower"
   ],
   [
    "equiv_err",
    "3.74 × 10⁻⁷ [3.38 × 10⁻⁷, 4.10 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.941 [0.927, 0.956]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0256 [0.0249, 0.0261]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__iid__sdnn__acc__torch__matched-100000": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__iid__sdnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.119 [0.113, 0.123]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0933 [0.0887, 0.0966]",
    "lower"
   ],
   [
    "equiv_err",
    "2.88 × 10⁻⁷ [2.52 × 10⁻⁷, 3.25 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "99 810",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "iid",
  "title": "sdnn (acc, torch), matched at 100 000 parameters"
 },
 "magneto-climb-small-v7__converge__unseen-heading__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.187 [0.183, 0.190]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.147 [0.144, 0.150]",
    "lower"
   ],
   [
    "equiv_err",
    "0.361 [0.333, 0.393]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.8 [25.4, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-heading__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.666 [0.624, 0.701]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.524 [0.492, 0.550]",
    "lower"
   ],
   [
    "equiv_err",
    "0.889 [0.832, 0.940]",
    "lower"
   ],
   [
    "invar_change",
    "1.29 [1.26, 1.32]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-heading__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.936 [0.903, 0.982]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.736 [0.711, 0.771]",
    "lower"
   ],
   [
    "equiv_err",
    "1.34 [1.19, 1.43]",
    "lower"
   ],
   [
    "invar_change",
    "1.59 [1.50, 1.69]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 700 [9 100, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.2 [23.6, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-heading__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.156 [0.151, 0.161]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.123 [0.119, 0.127]",
    "lower"
   ],
   [
    "equiv_err",
    "3.74 × 10⁻⁷ [2.84 × 10⁻⁷, 4.78 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-heading__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-heading",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.125 [0.123, 0.126]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0981 [0.0967, 0.0994]",
    "lower"
   ],
   [
    "equiv_err",
    "2.77 × 10⁻⁷ [2.43 × 10⁻⁷, 3.12 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-heading",
  "title": "sdnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-rotation__ffnn-leg__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.607 [0.587, 0.625]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.170 [0.159, 0.185]",
    "higher"
   ],
   [
    "cl_score",
    "0.236 [0.228, 0.243]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.476 [0.460, 0.490]",
    "lower"
   ],
   [
    "equiv_err",
    "0.729 [0.672, 0.796]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.615 [0.599, 0.632]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0759 [0.0704, 0.0803]",
    "lower"
   ],
   [
    "parameters",
    "158 988",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "27.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "1.02 [0.97, 1.06]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0540 [0.0436, 0.0633]",
    "higher"
   ],
   [
    "cl_score",
    "0.0711 [0.0592, 0.0830]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.796 [0.757, 0.835]",
    "lower"
   ],
   [
    "equiv_err",
    "1.12 [1.00, 1.22]",
    "lower"
   ],
   [
    "invar_change",
    "1.31 [1.24, 1.38]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.321 [0.292, 0.348]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0812 [0.0793, 0.0831]",
    "lower"
   ],
   [
    "parameters",
    "150 796",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "9 100 [7 300, 10 000]",
    ""
   ],
   [
    "epochs",
    "24.4 [19.2, 27.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-rotation__gnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3-4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.618 [0.605, 0.628]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.107 [0.099, 0.117]",
    "higher"
   ],
   [
    "cl_score",
    "0.151 [0.138, 0.169]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.484 [0.474, 0.493]",
    "lower"
   ],
   [
    "equiv_err",
    "1.18 [1.03, 1.34]",
    "lower"
   ],
   [
    "invar_change",
    "1.49 [1.40, 1.58]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.465 [0.442, 0.498]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0739 [0.0721, 0.0756]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.027",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "27.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "gnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-rotation__sdgnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.157 [0.154, 0.161]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.402 [0.390, 0.414]",
    "higher"
   ],
   [
    "cl_score",
    "0.427 [0.414, 0.437]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.123 [0.121, 0.126]",
    "lower"
   ],
   [
    "equiv_err",
    "3.66 × 10⁻⁷ [2.93 × 10⁻⁷, 4.62 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.956 [0.933, 0.979]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0293 [0.0276, 0.0313]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "27.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "magneto-climb-small-v7__converge__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/magneto__magneto-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "magneto-climb-small-v7",
  "entry": "entries/magneto-climb-small-v7__converge__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.129 [0.126, 0.133]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.410 [0.390, 0.431]",
    "higher"
   ],
   [
    "cl_score",
    "0.428 [0.402, 0.456]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.101 [0.098, 0.105]",
    "lower"
   ],
   [
    "equiv_err",
    "2.63 × 10⁻⁷ [2.18 × 10⁻⁷, 3.09 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.959 [0.912, 1.003]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0270 [0.0255, 0.0289]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "27.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "magneto",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-heading__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0954 [0.0902, 0.0997]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.165 [0.156, 0.172]",
    "lower"
   ],
   [
    "equiv_err",
    "0.840 [0.725, 0.955]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.8 [25.4, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-heading__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.255 [0.238, 0.269]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.439 [0.413, 0.461]",
    "lower"
   ],
   [
    "equiv_err",
    "1.11 [1.01, 1.20]",
    "lower"
   ],
   [
    "invar_change",
    "1.24 [1.10, 1.39]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "9 400 [8 200, 10 000]",
    ""
   ],
   [
    "epochs",
    "24.4 [21.2, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-heading",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-heading__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.181 [0.165, 0.198]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.312 [0.286, 0.339]",
    "lower"
   ],
   [
    "equiv_err",
    "0.650 [0.568, 0.742]",
    "lower"
   ],
   [
    "invar_change",
    "1.43 [1.22, 1.66]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 600 [8 800, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.0 [23.0, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-heading",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-heading__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0317 [0.0305, 0.0328]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0546 [0.0529, 0.0564]",
    "lower"
   ],
   [
    "equiv_err",
    "3.34 × 10⁻⁷ [2.94 × 10⁻⁷, 3.79 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-heading",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-heading__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0260 [0.0249, 0.0273]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0448 [0.0432, 0.0466]",
    "lower"
   ],
   [
    "equiv_err",
    "3.07 × 10⁻⁷ [2.81 × 10⁻⁷, 3.29 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.8 [25.4, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-heading",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-rotation__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.236 [0.224, 0.247]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.407 [0.386, 0.427]",
    "lower"
   ],
   [
    "equiv_err",
    "1.24 [1.12, 1.35]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "8 000 [6 700, 9 200]",
    ""
   ],
   [
    "epochs",
    "81.2 [68.0, 93.6]",
    ""
   ],
   [
    "stopped_by",
    "patience 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-rotation__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.473 [0.447, 0.498]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.815 [0.772, 0.861]",
    "lower"
   ],
   [
    "equiv_err",
    "1.16 [1.06, 1.26]",
    "lower"
   ],
   [
    "invar_change",
    "1.17 [1.06, 1.29]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "9 000 [7 000, 10 000]",
    ""
   ],
   [
    "epochs",
    "91.8 [71.4, 102.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-rotation",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-rotation__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.387 [0.360, 0.415]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.667 [0.621, 0.713]",
    "lower"
   ],
   [
    "equiv_err",
    "1.12 [1.01, 1.23]",
    "lower"
   ],
   [
    "invar_change",
    "1.28 [1.12, 1.43]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "6 000 [4 300, 7 600]",
    ""
   ],
   [
    "epochs",
    "60.6 [43.2, 77.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-rotation",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-rotation__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0552 [0.0527, 0.0573]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0951 [0.0912, 0.0988]",
    "lower"
   ],
   [
    "equiv_err",
    "4.04 × 10⁻⁷ [3.61 × 10⁻⁷, 4.43 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "102",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__control-rotation__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--control-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__control-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0515 [0.0485, 0.0549]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0887 [0.0842, 0.0941]",
    "lower"
   ],
   [
    "equiv_err",
    "4.13 × 10⁻⁷ [3.62 × 10⁻⁷, 4.63 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "8 700 [7 300, 10 000]",
    ""
   ],
   [
    "epochs",
    "88.6 [74.2, 102.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "control-rotation",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.1__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.1__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.326 [0.315, 0.341]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.562 [0.545, 0.588]",
    "lower"
   ],
   [
    "equiv_err",
    "1.26 [1.11, 1.49]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 100 [8 500, 9 600]",
    ""
   ],
   [
    "epochs",
    "159 [149, 168]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.1__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.1__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.520 [0.498, 0.532]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.897 [0.856, 0.925]",
    "lower"
   ],
   [
    "equiv_err",
    "1.29 [1.20, 1.36]",
    "lower"
   ],
   [
    "invar_change",
    "1.23 [1.08, 1.40]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "7 400 [4 800, 10 000]",
    ""
   ],
   [
    "epochs",
    "129 [84, 175]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.1__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.1__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.454 [0.441, 0.468]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.782 [0.761, 0.804]",
    "lower"
   ],
   [
    "equiv_err",
    "1.21 [1.06, 1.38]",
    "lower"
   ],
   [
    "invar_change",
    "1.37 [1.20, 1.55]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "6 300 [5 100, 7 500]",
    ""
   ],
   [
    "epochs",
    "110 [89, 131]",
    ""
   ],
   [
    "stopped_by",
    "patience 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.1__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.1__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0868 [0.0764, 0.0949]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.150 [0.132, 0.163]",
    "lower"
   ],
   [
    "equiv_err",
    "3.38 × 10⁻⁷ [2.86 × 10⁻⁷, 4.16 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 100 [7 300, 10 000]",
    ""
   ],
   [
    "epochs",
    "159 [128, 175]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.1__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-1",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.1__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0855 [0.0766, 0.0926]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.147 [0.133, 0.158]",
    "lower"
   ],
   [
    "equiv_err",
    "3.13 × 10⁻⁷ [2.88 × 10⁻⁷, 3.34 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "8 000 [6 600, 9 400]",
    ""
   ],
   [
    "epochs",
    "140 [116, 164]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.1",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.25__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.25__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.201 [0.184, 0.219]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.347 [0.315, 0.382]",
    "lower"
   ],
   [
    "equiv_err",
    "0.940 [0.875, 1.011]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "7 900 [6 700, 9 200]",
    ""
   ],
   [
    "epochs",
    "54.0 [45.8, 62.8]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.25__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.25__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.425 [0.400, 0.449]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.733 [0.689, 0.777]",
    "lower"
   ],
   [
    "equiv_err",
    "1.22 [1.06, 1.39]",
    "lower"
   ],
   [
    "invar_change",
    "1.23 [1.09, 1.40]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "8 800 [6 400, 10 000]",
    ""
   ],
   [
    "epochs",
    "59.8 [43.4, 68.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.25__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.25__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.332 [0.305, 0.360]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.573 [0.524, 0.623]",
    "lower"
   ],
   [
    "equiv_err",
    "1.01 [0.90, 1.12]",
    "lower"
   ],
   [
    "invar_change",
    "1.21 [1.08, 1.34]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "6 000 [4 800, 8 000]",
    ""
   ],
   [
    "epochs",
    "40.8 [32.8, 54.4]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.25__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.25__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0436 [0.0407, 0.0465]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0751 [0.0702, 0.0801]",
    "lower"
   ],
   [
    "equiv_err",
    "2.84 × 10⁻⁷ [2.64 × 10⁻⁷, 3.15 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "68.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.25__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-25",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.25__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0405 [0.0371, 0.0440]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0698 [0.0640, 0.0755]",
    "lower"
   ],
   [
    "equiv_err",
    "3.05 × 10⁻⁷ [2.75 × 10⁻⁷, 3.35 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "68.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.25",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.5__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.5__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.120 [0.113, 0.126]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.207 [0.196, 0.217]",
    "lower"
   ],
   [
    "equiv_err",
    "0.752 [0.654, 0.830]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 400 [8 600, 10 000]",
    ""
   ],
   [
    "epochs",
    "32.0 [29.2, 34.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.5__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.5__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.295 [0.278, 0.318]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.508 [0.483, 0.545]",
    "lower"
   ],
   [
    "equiv_err",
    "1.11 [1.03, 1.18]",
    "lower"
   ],
   [
    "invar_change",
    "1.09 [1.01, 1.18]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "33.8 [33.4, 34.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.5__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.5__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.212 [0.189, 0.246]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.365 [0.326, 0.423]",
    "lower"
   ],
   [
    "equiv_err",
    "0.721 [0.675, 0.763]",
    "lower"
   ],
   [
    "invar_change",
    "1.43 [1.29, 1.57]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "8 100 [5 900, 10 000]",
    ""
   ],
   [
    "epochs",
    "27.4 [19.8, 34.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 2, patience 3",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.5__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.5__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0328 [0.0315, 0.0340]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0565 [0.0545, 0.0582]",
    "lower"
   ],
   [
    "equiv_err",
    "3.25 × 10⁻⁷ [3.16 × 10⁻⁷, 3.35 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "34.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.5__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-5",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.5__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0284 [0.0267, 0.0301]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0489 [0.0461, 0.0517]",
    "lower"
   ],
   [
    "equiv_err",
    "2.94 × 10⁻⁷ [2.74 × 10⁻⁷, 3.14 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "34.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.5",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.75__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.75__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0907 [0.0868, 0.0954]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.156 [0.150, 0.165]",
    "lower"
   ],
   [
    "equiv_err",
    "0.777 [0.694, 0.862]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "22.8 [22.4, 23.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.75__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.75__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.235 [0.217, 0.254]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.405 [0.374, 0.437]",
    "lower"
   ],
   [
    "equiv_err",
    "1.03 [0.91, 1.14]",
    "lower"
   ],
   [
    "invar_change",
    "1.10 [1.01, 1.20]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.75__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.75__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.169 [0.158, 0.180]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.292 [0.271, 0.312]",
    "lower"
   ],
   [
    "equiv_err",
    "0.747 [0.694, 0.799]",
    "lower"
   ],
   [
    "invar_change",
    "1.38 [1.17, 1.61]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 500 [8 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "21.8 [19.4, 23.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.75__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.75__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0310 [0.0299, 0.0321]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0535 [0.0518, 0.0552]",
    "lower"
   ],
   [
    "equiv_err",
    "2.83 × 10⁻⁷ [2.66 × 10⁻⁷, 3.04 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__fraction-0.75__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--fraction-0-75",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__fraction-0.75__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0251 [0.0237, 0.0267]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0433 [0.0409, 0.0458]",
    "lower"
   ],
   [
    "equiv_err",
    "2.89 × 10⁻⁷ [2.66 × 10⁻⁷, 3.13 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "23.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "fraction-0.75",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__iid__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0776 [0.0742, 0.0809]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.506 [0.495, 0.517]",
    "higher"
   ],
   [
    "cl_score",
    "0.581 [0.569, 0.592]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.134 [0.129, 0.139]",
    "lower"
   ],
   [
    "equiv_err",
    "0.743 [0.655, 0.844]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.263 [0.250, 0.275]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.32 [1.30, 1.34]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0394 [0.0367, 0.0420]",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__iid__ffnn-leg__acc__torch__matched-100000": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__ffnn-leg__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0806 [0.0786, 0.0833]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.139 [0.136, 0.143]",
    "lower"
   ],
   [
    "equiv_err",
    "0.709 [0.605, 0.803]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "100 303",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "ffnn-leg (acc, torch), matched at 100 000 parameters"
 },
 "nona-climb-small-v7__converge__iid__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.193 [0.180, 0.205]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.367 [0.355, 0.377]",
    "higher"
   ],
   [
    "cl_score",
    "0.489 [0.453, 0.527]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.333 [0.312, 0.352]",
    "lower"
   ],
   [
    "equiv_err",
    "0.948 [0.872, 1.002]",
    "lower"
   ],
   [
    "invar_change",
    "1.12 [1.01, 1.22]",
    "lower"
   ],
   [
    "cl_success",
    "0.113 [0.069, 0.169]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.17 [1.11, 1.23]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0624 [0.0576, 0.0680]",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__iid__ffnn__acc__torch__matched-100000": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__ffnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.197 [0.183, 0.211]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.340 [0.318, 0.362]",
    "lower"
   ],
   [
    "equiv_err",
    "1.02 [0.87, 1.19]",
    "lower"
   ],
   [
    "invar_change",
    "1.14 [1.10, 1.18]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "100 157",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "ffnn (acc, torch), matched at 100 000 parameters"
 },
 "nona-climb-small-v7__converge__iid__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.128 [0.115, 0.147]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.406 [0.376, 0.431]",
    "higher"
   ],
   [
    "cl_score",
    "0.553 [0.519, 0.579]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.222 [0.198, 0.252]",
    "lower"
   ],
   [
    "equiv_err",
    "0.553 [0.518, 0.604]",
    "lower"
   ],
   [
    "invar_change",
    "1.33 [1.22, 1.44]",
    "lower"
   ],
   [
    "cl_success",
    "0.175 [0.119, 0.212]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.27 [1.21, 1.31]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0684 [0.0641, 0.0728]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__iid__gnn__acc__torch__matched-100000": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__gnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.129 [0.114, 0.142]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.222 [0.198, 0.245]",
    "lower"
   ],
   [
    "equiv_err",
    "0.717 [0.683, 0.760]",
    "lower"
   ],
   [
    "invar_change",
    "1.38 [1.25, 1.53]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "99 381",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 900 [9 700, 10 000]",
    ""
   ],
   [
    "epochs",
    "16.8 [16.4, 17.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "gnn (acc, torch), matched at 100 000 parameters"
 },
 "nona-climb-small-v7__converge__iid__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0282 [0.0270, 0.0295]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.601 [0.557, 0.645]",
    "higher"
   ],
   [
    "cl_score",
    "0.700 [0.630, 0.770]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0487 [0.0464, 0.0510]",
    "lower"
   ],
   [
    "equiv_err",
    "3.97 × 10⁻⁷ [3.79 × 10⁻⁷, 4.16 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.356 [0.263, 0.450]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.51 [1.40, 1.62]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0404 [0.0351, 0.0458]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__iid__sdgnn__acc__torch__matched-100000": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__sdgnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0255 [0.0245, 0.0265]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0440 [0.0426, 0.0453]",
    "lower"
   ],
   [
    "equiv_err",
    "3.35 × 10⁻⁷ [2.81 × 10⁻⁷, 3.88 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "100 299",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "sdgnn (acc, torch), matched at 100 000 parameters"
 },
 "nona-climb-small-v7__converge__iid__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0231 [0.0225, 0.0238]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.606 [0.563, 0.649]",
    "higher"
   ],
   [
    "cl_score",
    "0.692 [0.632, 0.754]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0399 [0.0387, 0.0410]",
    "lower"
   ],
   [
    "equiv_err",
    "4.24 × 10⁻⁷ [3.88 × 10⁻⁷, 4.58 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.381 [0.263, 0.500]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.50 [1.40, 1.60]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0376 [0.0343, 0.0414]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__iid__sdnn__acc__torch__matched-100000": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--matched-100000--iid",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__iid__sdnn__acc__torch__matched-100000.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0241 [0.0236, 0.0246]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0416 [0.0407, 0.0424]",
    "lower"
   ],
   [
    "equiv_err",
    "3.13 × 10⁻⁷ [2.86 × 10⁻⁷, 3.34 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "99 810",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "17.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "iid",
  "title": "sdnn (acc, torch), matched at 100 000 parameters"
 },
 "nona-climb-small-v7__converge__unseen-heading__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-heading__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0980 [0.0944, 0.1010]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.168 [0.162, 0.173]",
    "lower"
   ],
   [
    "equiv_err",
    "0.722 [0.678, 0.766]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "9 800 [9 400, 10 000]",
    ""
   ],
   [
    "epochs",
    "25.4 [24.2, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-heading__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-heading__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.361 [0.350, 0.369]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.619 [0.601, 0.632]",
    "lower"
   ],
   [
    "equiv_err",
    "1.14 [1.06, 1.20]",
    "lower"
   ],
   [
    "invar_change",
    "1.30 [1.23, 1.37]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "9 200 [7 600, 10 000]",
    ""
   ],
   [
    "epochs",
    "23.8 [19.4, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-heading__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-heading__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4-5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.354 [0.330, 0.375]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.607 [0.565, 0.642]",
    "lower"
   ],
   [
    "equiv_err",
    "0.932 [0.860, 0.993]",
    "lower"
   ],
   [
    "invar_change",
    "1.52 [1.42, 1.64]",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 400 [8 200, 10 000]",
    ""
   ],
   [
    "epochs",
    "24.4 [21.2, 26.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-heading__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-heading__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0314 [0.0302, 0.0325]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0538 [0.0519, 0.0556]",
    "lower"
   ],
   [
    "equiv_err",
    "3.20 × 10⁻⁷ [2.86 × 10⁻⁷, 3.57 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-heading__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-heading",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-heading__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0248 [0.0241, 0.0257]",
    "lower"
   ],
   [
    "cl_tracking",
    "-",
    "higher"
   ],
   [
    "cl_score",
    "-",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0425 [0.0413, 0.0439]",
    "lower"
   ],
   [
    "equiv_err",
    "3.02 × 10⁻⁷ [2.75 × 10⁻⁷, 3.29 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "-",
    "higher"
   ],
   [
    "cl_held_s",
    "-",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "-",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "10 000",
    ""
   ],
   [
    "epochs",
    "26.0",
    ""
   ],
   [
    "stopped_by",
    "budget 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-heading",
  "title": "sdnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-rotation__ffnn-leg__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-rotation__ffnn-leg__acc__torch.html",
  "metrics": [
   [
    "rank",
    "4",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.612 [0.584, 0.642]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.120 [0.116, 0.124]",
    "higher"
   ],
   [
    "cl_score",
    "0.265 [0.259, 0.271]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.06 [1.01, 1.11]",
    "lower"
   ],
   [
    "equiv_err",
    "1.73 [1.53, 1.99]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.0312 [0.0063, 0.0625]",
    "higher"
   ],
   [
    "cl_held_s",
    "0.812 [0.793, 0.831]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.118 [0.115, 0.122]",
    "lower"
   ],
   [
    "parameters",
    "192 283",
    ""
   ],
   [
    "learning_rate",
    "0.001",
    ""
   ],
   [
    "steps",
    "7 900 [5 500, 10 000]",
    ""
   ],
   [
    "epochs",
    "80.4 [55.6, 102.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 1, patience 4",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "ffnn-leg (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-rotation__ffnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-rotation__ffnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "5",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.723 [0.708, 0.747]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.0144 [0.0042, 0.0247]",
    "higher"
   ],
   [
    "cl_score",
    "0.0466 [0.0205, 0.0752]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "1.25 [1.22, 1.29]",
    "lower"
   ],
   [
    "equiv_err",
    "1.40 [1.36, 1.45]",
    "lower"
   ],
   [
    "invar_change",
    "1.14 [1.08, 1.20]",
    "lower"
   ],
   [
    "cl_success",
    "0",
    "higher"
   ],
   [
    "cl_held_s",
    "0.460 [0.432, 0.490]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.122 [0.116, 0.128]",
    "lower"
   ],
   [
    "parameters",
    "168 731",
    ""
   ],
   [
    "learning_rate",
    "0.081",
    ""
   ],
   [
    "steps",
    "7 700 [5 300, 10 000]",
    ""
   ],
   [
    "epochs",
    "78.2 [53.4, 102.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "ffnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-rotation__gnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-rotation__gnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "3",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.407 [0.394, 0.419]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.326 [0.294, 0.349]",
    "higher"
   ],
   [
    "cl_score",
    "0.491 [0.454, 0.529]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.703 [0.682, 0.723]",
    "lower"
   ],
   [
    "equiv_err",
    "1.14 [1.08, 1.22]",
    "lower"
   ],
   [
    "invar_change",
    "1.46 [1.39, 1.52]",
    "lower"
   ],
   [
    "cl_success",
    "0.113 [0.069, 0.156]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.18 [1.12, 1.24]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0794 [0.0735, 0.0864]",
    "lower"
   ],
   [
    "parameters",
    "90 177",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "6 500 [4 900, 8 100]",
    ""
   ],
   [
    "epochs",
    "65.6 [49.2, 82.0]",
    ""
   ],
   [
    "stopped_by",
    "patience 5",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "gnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-rotation__sdgnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-rotation__sdgnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0542 [0.0513, 0.0587]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.587 [0.542, 0.636]",
    "higher"
   ],
   [
    "cl_score",
    "0.671 [0.608, 0.733]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0936 [0.0887, 0.1016]",
    "lower"
   ],
   [
    "equiv_err",
    "4.08 × 10⁻⁷ [3.87 × 10⁻⁷, 4.28 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.331 [0.275, 0.388]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.47 [1.36, 1.57]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0378 [0.0355, 0.0401]",
    "lower"
   ],
   [
    "parameters",
    "45 619",
    ""
   ],
   [
    "learning_rate",
    "0.003",
    ""
   ],
   [
    "steps",
    "9 700 [9 100, 10 000]",
    ""
   ],
   [
    "epochs",
    "98.8 [92.4, 102.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 4, patience 1",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "sdgnn (acc, torch)"
 },
 "nona-climb-small-v7__converge__unseen-rotation__sdnn__acc__torch": {
  "board": "boards/nona__nona-climb-small-v7.html#converge--unseen-rotation",
  "dataset": "nona-climb-small-v7",
  "entry": "entries/nona-climb-small-v7__converge__unseen-rotation__sdnn__acc__torch.html",
  "metrics": [
   [
    "rank",
    "1-2",
    "lower"
   ],
   [
    "rmse_Nm",
    "0.0534 [0.0495, 0.0586]",
    "lower"
   ],
   [
    "cl_tracking",
    "0.570 [0.545, 0.598]",
    "higher"
   ],
   [
    "cl_score",
    "0.674 [0.624, 0.723]",
    "higher"
   ],
   [
    "variant",
    "acc",
    ""
   ],
   [
    "backend",
    "torch",
    ""
   ],
   [
    "nrmse",
    "0.0923 [0.0860, 0.1014]",
    "lower"
   ],
   [
    "equiv_err",
    "4.19 × 10⁻⁷ [3.92 × 10⁻⁷, 4.43 × 10⁻⁷]",
    "lower"
   ],
   [
    "invar_change",
    "0",
    "lower"
   ],
   [
    "cl_success",
    "0.388 [0.294, 0.475]",
    "higher"
   ],
   [
    "cl_held_s",
    "1.47 [1.39, 1.55]",
    "higher"
   ],
   [
    "cl_rmse_rad",
    "0.0399 [0.0352, 0.0452]",
    "lower"
   ],
   [
    "parameters",
    "152 835",
    ""
   ],
   [
    "learning_rate",
    "0.0015",
    ""
   ],
   [
    "steps",
    "8 600 [6 600, 10 000]",
    ""
   ],
   [
    "epochs",
    "87.6 [67.2, 102.0]",
    ""
   ],
   [
    "stopped_by",
    "budget 3, patience 2",
    ""
   ],
   [
    "seeds",
    "5",
    ""
   ]
  ],
  "protocol": "converge",
  "robot": "nona",
  "split": "unseen-rotation",
  "title": "sdnn (acc, torch)"
 }
};
