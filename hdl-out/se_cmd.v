

module se_cmd(clock,width,inp$valid,inp$ready,inp$y,inp$xl,inp$xr,inp$left_z,inp$left_c0,inp$left_c1,inp$left_c2,inp$right_z,inp$right_c0,inp$right_c1,inp$right_c2,inp$ddx_z,inp$ddx_c0,inp$ddx_c1,inp$ddx_c2,out_valid,out_ready,xl,xr,za,zb,ra,rb,ga,gb,ba,bb,rd_y,wr_y,idle,engines_idle);
    
    // Module arguments
    input wire  clock;
    input wire  [10:0] width;
    input wire  inp$valid;
    output reg  inp$ready;
    input wire  [9:0] inp$y;
    input wire  [12:0] inp$xl;
    input wire  [12:0] inp$xr;
    input wire  [35:0] inp$left_z;
    input wire  [31:0] inp$left_c0;
    input wire  [31:0] inp$left_c1;
    input wire  [31:0] inp$left_c2;
    input wire  [35:0] inp$right_z;
    input wire  [31:0] inp$right_c0;
    input wire  [31:0] inp$right_c1;
    input wire  [31:0] inp$right_c2;
    input wire  [39:0] inp$ddx_z;
    input wire  [35:0] inp$ddx_c0;
    input wire  [35:0] inp$ddx_c1;
    input wire  [35:0] inp$ddx_c2;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [12:0] xl;
    output reg  [12:0] xr;
    output reg  [44:0] za;
    output reg  [44:0] zb;
    output reg  [36:0] ra;
    output reg  [36:0] rb;
    output reg  [36:0] ga;
    output reg  [36:0] gb;
    output reg  [36:0] ba;
    output reg  [36:0] bb;
    output reg  [9:0] rd_y;
    output reg  [9:0] wr_y;
    output reg  idle;
    output reg  engines_idle;
    
    // Constant declarations
    localparam  pixel = 5'b1101;
    localparam  ii = 8'h9c;
    localparam  latency = 8'hb5;
    localparam  writes = 8'ha5;
    
    // Stub signals
    reg  attr_z$clock;
    reg  attr_z$load;
    reg  [35:0] attr_z$v0;
    reg  [39:0] attr_z$step;
    reg  attr_z$run;
    reg  attr_z$x0_bit;
    reg  attr_z$last;
    wire  [44:0] attr_z$a;
    wire  [44:0] attr_z$b;
    reg  attr_r$clock;
    reg  attr_r$load;
    reg  [31:0] attr_r$v0;
    reg  [35:0] attr_r$step;
    reg  attr_r$run;
    reg  attr_r$x0_bit;
    reg  attr_r$last;
    wire  [36:0] attr_r$a;
    wire  [36:0] attr_r$b;
    reg  attr_g$clock;
    reg  attr_g$load;
    reg  [31:0] attr_g$v0;
    reg  [35:0] attr_g$step;
    reg  attr_g$run;
    reg  attr_g$x0_bit;
    reg  attr_g$last;
    wire  [36:0] attr_g$a;
    wire  [36:0] attr_g$b;
    reg  attr_b$clock;
    reg  attr_b$load;
    reg  [31:0] attr_b$v0;
    reg  [35:0] attr_b$step;
    reg  attr_b$run;
    reg  attr_b$x0_bit;
    reg  attr_b$last;
    wire  [36:0] attr_b$a;
    wire  [36:0] attr_b$b;
    reg  busy$d;
    wire  busy$q;
    reg  busy$clock;
    reg  [4:0] k$d;
    wire  [4:0] k$q;
    reg  k$clock;
    reg  [12:0] x0s$d;
    wire  [12:0] x0s$q;
    reg  x0s$clock;
    reg  [9:0] y$d;
    wire  [9:0] y$q;
    reg  y$clock;
    reg  [12:0] cxl$d;
    wire  [12:0] cxl$q;
    reg  cxl$clock;
    reg  [12:0] cxr$d;
    wire  [12:0] cxr$q;
    reg  cxr$clock;
    reg  started$d;
    wire  started$q;
    reg  started$clock;
    reg  [7:0] since$d;
    wire  [7:0] since$q;
    reg  since$clock;
    reg  [9:0] last_y$d;
    wire  [9:0] last_y$q;
    reg  last_y$clock;
    reg  [9:0] prev_y$d;
    wire  [9:0] prev_y$q;
    reg  prev_y$clock;
    reg  [12:0] xl_neg$x;
    wire  xl_neg$neg;
    reg  [12:0] xr_neg$x;
    wire  xr_neg$neg;
    
    // Local signals
    reg  load;
    reg  run;
    reg  [7:0] gap;
    reg  issue;
    
    // Sub module instances
    se_cmd$attr_z attr_z(
        .clock(attr_z$clock),
        .load(attr_z$load),
        .v0(attr_z$v0),
        .step(attr_z$step),
        .run(attr_z$run),
        .x0_bit(attr_z$x0_bit),
        .last(attr_z$last),
        .a(attr_z$a),
        .b(attr_z$b)
    );
    se_cmd$attr_r attr_r(
        .clock(attr_r$clock),
        .load(attr_r$load),
        .v0(attr_r$v0),
        .step(attr_r$step),
        .run(attr_r$run),
        .x0_bit(attr_r$x0_bit),
        .last(attr_r$last),
        .a(attr_r$a),
        .b(attr_r$b)
    );
    se_cmd$attr_g attr_g(
        .clock(attr_g$clock),
        .load(attr_g$load),
        .v0(attr_g$v0),
        .step(attr_g$step),
        .run(attr_g$run),
        .x0_bit(attr_g$x0_bit),
        .last(attr_g$last),
        .a(attr_g$a),
        .b(attr_g$b)
    );
    se_cmd$attr_b attr_b(
        .clock(attr_b$clock),
        .load(attr_b$load),
        .v0(attr_b$v0),
        .step(attr_b$step),
        .run(attr_b$run),
        .x0_bit(attr_b$x0_bit),
        .last(attr_b$last),
        .a(attr_b$a),
        .b(attr_b$b)
    );
    se_cmd$busy busy(
        .d(busy$d),
        .q(busy$q),
        .clock(busy$clock)
    );
    se_cmd$k k(
        .d(k$d),
        .q(k$q),
        .clock(k$clock)
    );
    se_cmd$x0s x0s(
        .d(x0s$d),
        .q(x0s$q),
        .clock(x0s$clock)
    );
    se_cmd$y y(
        .d(y$d),
        .q(y$q),
        .clock(y$clock)
    );
    se_cmd$cxl cxl(
        .d(cxl$d),
        .q(cxl$q),
        .clock(cxl$clock)
    );
    se_cmd$cxr cxr(
        .d(cxr$d),
        .q(cxr$q),
        .clock(cxr$clock)
    );
    se_cmd$started started(
        .d(started$d),
        .q(started$q),
        .clock(started$clock)
    );
    se_cmd$since since(
        .d(since$d),
        .q(since$q),
        .clock(since$clock)
    );
    se_cmd$last_y last_y(
        .d(last_y$d),
        .q(last_y$q),
        .clock(last_y$clock)
    );
    se_cmd$prev_y prev_y(
        .d(prev_y$d),
        .q(prev_y$q),
        .clock(prev_y$clock)
    );
    se_cmd$xl_neg xl_neg(
        .x(xl_neg$x),
        .neg(xl_neg$neg)
    );
    se_cmd$xr_neg xr_neg(
        .x(xr_neg$x),
        .neg(xr_neg$neg)
    );
    
    // Update code
    always @(*) begin
        busy$clock = clock;
        k$clock = clock;
        x0s$clock = clock;
        y$clock = clock;
        cxl$clock = clock;
        cxr$clock = clock;
        started$clock = clock;
        since$clock = clock;
        last_y$clock = clock;
        prev_y$clock = clock;
        busy$d = busy$q;
        k$d = k$q;
        x0s$d = x0s$q;
        y$d = y$q;
        cxl$d = cxl$q;
        cxr$d = cxr$q;
        started$d = started$q;
        since$d = since$q;
        last_y$d = last_y$q;
        prev_y$d = prev_y$q;
        attr_z$clock = clock;
        attr_r$clock = clock;
        attr_g$clock = clock;
        attr_b$clock = clock;
        xl_neg$x = inp$xl;
        xr_neg$x = inp$xr;
        inp$ready = ~busy$q;
        load = inp$valid & ~busy$q & ~xr_neg$neg & (xl_neg$neg | (inp$xl < ((width) & 13'h1fff)));
        attr_z$v0 = inp$left_z;
        attr_r$v0 = inp$left_c0;
        attr_g$v0 = inp$left_c1;
        attr_b$v0 = inp$left_c2;
        if (load) begin
            x0s$d = inp$xl;
        end
        if (xl_neg$neg) begin
            attr_z$v0 = inp$right_z;
            attr_r$v0 = inp$right_c0;
            attr_g$v0 = inp$right_c1;
            attr_b$v0 = inp$right_c2;
            if (load) begin
                x0s$d = inp$xr;
            end
        end
        attr_z$step = inp$ddx_z;
        attr_r$step = inp$ddx_c0;
        attr_g$step = inp$ddx_c1;
        attr_b$step = inp$ddx_c2;
        if (load) begin
            busy$d = 1'b1;
            k$d = 32'h0;
            y$d = inp$y;
            cxl$d = inp$xl;
            cxr$d = inp$xr;
        end
        run = busy$q & (k$q != pixel);
        if (run) begin
            k$d = k$q + 32'h1;
            x0s$d = x0s$q >> 32'h1;
        end
        attr_z$load = load;
        attr_z$run = run;
        attr_z$x0_bit = x0s$q[32'h0];
        attr_z$last = k$q == (pixel - 32'h1);
        attr_r$load = load;
        attr_r$run = run;
        attr_r$x0_bit = x0s$q[32'h0];
        attr_r$last = k$q == (pixel - 32'h1);
        attr_g$load = load;
        attr_g$run = run;
        attr_g$x0_bit = x0s$q[32'h0];
        attr_g$last = k$q == (pixel - 32'h1);
        attr_b$load = load;
        attr_b$run = run;
        attr_b$x0_bit = x0s$q[32'h0];
        attr_b$last = k$q == (pixel - 32'h1);
        gap = ii;
        if (y$q == last_y$q) begin
            gap = latency;
        end
        out_valid = busy$q & (k$q == pixel) & (~started$q | (since$q >= gap));
        xl = cxl$q;
        xr = cxr$q;
        za = attr_z$a;
        zb = attr_z$b;
        ra = attr_r$a;
        rb = attr_r$b;
        ga = attr_g$a;
        gb = attr_g$b;
        ba = attr_b$a;
        bb = attr_b$b;
        issue = out_valid & out_ready;
        if (since$q != 32'hff) begin
            since$d = since$q + 32'h1;
        end
        if (issue) begin
            busy$d = 1'b0;
            started$d = 1'b1;
            since$d = 32'h1;
            last_y$d = y$q;
            prev_y$d = last_y$q;
        end
        rd_y = last_y$q;
        wr_y = prev_y$q;
        if (since$q >= writes) begin
            wr_y = last_y$q;
        end
        idle = ~busy$q;
        engines_idle = ~started$q | (since$q >= latency);
    end
    
endmodule // se_cmd


module se_cmd$attr_b(clock,load,v0,step,run,x0_bit,last,a,b);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  [31:0] v0;
    input wire  [35:0] step;
    input wire  run;
    input wire  x0_bit;
    input wire  last;
    output reg  [36:0] a;
    output reg  [36:0] b;
    
    // Stub signals
    reg  [31:0] v0_q$d;
    wire  [31:0] v0_q$q;
    reg  v0_q$clock;
    reg  [35:0] step_q$d;
    wire  [35:0] step_q$q;
    reg  step_q$clock;
    reg  [49:0] sh$d;
    wire  [49:0] sh$q;
    reg  sh$clock;
    reg  [49:0] acc$d;
    wire  [49:0] acc$q;
    reg  acc$clock;
    reg  [35:0] ext_step$x;
    wire  [49:0] ext_step$y;
    reg  [31:0] ext_v0$x;
    wire  [49:0] ext_v0$y;
    reg  [35:0] line_a$x;
    wire  [36:0] line_a$y;
    reg  [49:0] line_b$x;
    wire  [36:0] line_b$y;
    
    // Sub module instances
    se_cmd$attr_b$v0_q v0_q(
        .d(v0_q$d),
        .q(v0_q$q),
        .clock(v0_q$clock)
    );
    se_cmd$attr_b$step_q step_q(
        .d(step_q$d),
        .q(step_q$q),
        .clock(step_q$clock)
    );
    se_cmd$attr_b$sh sh(
        .d(sh$d),
        .q(sh$q),
        .clock(sh$clock)
    );
    se_cmd$attr_b$acc acc(
        .d(acc$d),
        .q(acc$q),
        .clock(acc$clock)
    );
    se_cmd$attr_b$ext_step ext_step(
        .x(ext_step$x),
        .y(ext_step$y)
    );
    se_cmd$attr_b$ext_v0 ext_v0(
        .x(ext_v0$x),
        .y(ext_v0$y)
    );
    se_cmd$attr_b$line_a line_a(
        .x(line_a$x),
        .y(line_a$y)
    );
    se_cmd$attr_b$line_b line_b(
        .x(line_b$x),
        .y(line_b$y)
    );
    
    // Update code
    always @(*) begin
        v0_q$clock = clock;
        step_q$clock = clock;
        sh$clock = clock;
        acc$clock = clock;
        v0_q$d = v0_q$q;
        step_q$d = step_q$q;
        sh$d = sh$q;
        acc$d = acc$q;
        ext_step$x = step;
        ext_v0$x = v0_q$q;
        if (load) begin
            v0_q$d = v0;
            step_q$d = step;
            sh$d = ext_step$y;
            acc$d = 32'h0;
        end
        if (run) begin
            sh$d = sh$q << 32'h1;
            if (x0_bit & last) begin
                acc$d = acc$q - sh$q;
            end
            if (x0_bit & ~last) begin
                acc$d = acc$q + sh$q;
            end
        end
        line_a$x = step_q$q;
        line_b$x = ext_v0$y - acc$q;
        a = line_a$y;
        b = line_b$y;
    end
    
endmodule // se_cmd$attr_b


module se_cmd$attr_b$acc(d,q,clock);
    
    // Module arguments
    input wire  [49:0] d;
    output reg  [49:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 50'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_b$acc


module se_cmd$attr_b$ext_step(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [49:0] y;
    
    // Constant declarations
    localparam  msb = 8'h23;
    localparam  ext = 50'h3fff000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 50'h3ffffffffffff);
        if (x[msb]) begin
            y = ((x) & 50'h3ffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_b$ext_step


module se_cmd$attr_b$ext_v0(x,y);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  [49:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1f;
    localparam  ext = 50'h3ffff00000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 50'h3ffffffffffff);
        if (x[msb]) begin
            y = ((x) & 50'h3ffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_b$ext_v0


module se_cmd$attr_b$line_a(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [36:0] y;
    
    // Constant declarations
    localparam  frac = 8'h10;
    localparam  half = 89'h200000;
    localparam  s = 8'h16;
    
    // Stub signals
    reg  [35:0] widen$x;
    wire  [88:0] widen$y;
    
    // Sub module instances
    se_cmd$attr_b$line_a$widen widen(
        .x(widen$x),
        .y(widen$y)
    );
    
    // Update code
    always @(*) begin
        widen$x = x;
        y = ((((widen$y << frac) + half) >> s) & 37'h1fffffffff);
    end
    
endmodule // se_cmd$attr_b$line_a


module se_cmd$attr_b$line_a$widen(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [88:0] y;
    
    // Constant declarations
    localparam  msb = 8'h23;
    localparam  ext = 89'h1fffffffffffff000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 89'h1ffffffffffffffffffffff);
        if (x[msb]) begin
            y = ((x) & 89'h1ffffffffffffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_b$line_a$widen


module se_cmd$attr_b$line_b(x,y);
    
    // Module arguments
    input wire  [49:0] x;
    output reg  [36:0] y;
    
    // Constant declarations
    localparam  frac = 8'h10;
    localparam  half = 103'h200000;
    localparam  s = 8'h16;
    
    // Stub signals
    reg  [49:0] widen$x;
    wire  [102:0] widen$y;
    
    // Sub module instances
    se_cmd$attr_b$line_b$widen widen(
        .x(widen$x),
        .y(widen$y)
    );
    
    // Update code
    always @(*) begin
        widen$x = x;
        y = ((((widen$y << frac) + half) >> s) & 37'h1fffffffff);
    end
    
endmodule // se_cmd$attr_b$line_b


module se_cmd$attr_b$line_b$widen(x,y);
    
    // Module arguments
    input wire  [49:0] x;
    output reg  [102:0] y;
    
    // Constant declarations
    localparam  msb = 8'h31;
    localparam  ext = 103'h7ffffffffffffc000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 103'h7fffffffffffffffffffffffff);
        if (x[msb]) begin
            y = ((x) & 103'h7fffffffffffffffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_b$line_b$widen


module se_cmd$attr_b$sh(d,q,clock);
    
    // Module arguments
    input wire  [49:0] d;
    output reg  [49:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 50'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_b$sh


module se_cmd$attr_b$step_q(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_b$step_q


module se_cmd$attr_b$v0_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_b$v0_q


module se_cmd$attr_g(clock,load,v0,step,run,x0_bit,last,a,b);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  [31:0] v0;
    input wire  [35:0] step;
    input wire  run;
    input wire  x0_bit;
    input wire  last;
    output reg  [36:0] a;
    output reg  [36:0] b;
    
    // Stub signals
    reg  [31:0] v0_q$d;
    wire  [31:0] v0_q$q;
    reg  v0_q$clock;
    reg  [35:0] step_q$d;
    wire  [35:0] step_q$q;
    reg  step_q$clock;
    reg  [49:0] sh$d;
    wire  [49:0] sh$q;
    reg  sh$clock;
    reg  [49:0] acc$d;
    wire  [49:0] acc$q;
    reg  acc$clock;
    reg  [35:0] ext_step$x;
    wire  [49:0] ext_step$y;
    reg  [31:0] ext_v0$x;
    wire  [49:0] ext_v0$y;
    reg  [35:0] line_a$x;
    wire  [36:0] line_a$y;
    reg  [49:0] line_b$x;
    wire  [36:0] line_b$y;
    
    // Sub module instances
    se_cmd$attr_g$v0_q v0_q(
        .d(v0_q$d),
        .q(v0_q$q),
        .clock(v0_q$clock)
    );
    se_cmd$attr_g$step_q step_q(
        .d(step_q$d),
        .q(step_q$q),
        .clock(step_q$clock)
    );
    se_cmd$attr_g$sh sh(
        .d(sh$d),
        .q(sh$q),
        .clock(sh$clock)
    );
    se_cmd$attr_g$acc acc(
        .d(acc$d),
        .q(acc$q),
        .clock(acc$clock)
    );
    se_cmd$attr_g$ext_step ext_step(
        .x(ext_step$x),
        .y(ext_step$y)
    );
    se_cmd$attr_g$ext_v0 ext_v0(
        .x(ext_v0$x),
        .y(ext_v0$y)
    );
    se_cmd$attr_g$line_a line_a(
        .x(line_a$x),
        .y(line_a$y)
    );
    se_cmd$attr_g$line_b line_b(
        .x(line_b$x),
        .y(line_b$y)
    );
    
    // Update code
    always @(*) begin
        v0_q$clock = clock;
        step_q$clock = clock;
        sh$clock = clock;
        acc$clock = clock;
        v0_q$d = v0_q$q;
        step_q$d = step_q$q;
        sh$d = sh$q;
        acc$d = acc$q;
        ext_step$x = step;
        ext_v0$x = v0_q$q;
        if (load) begin
            v0_q$d = v0;
            step_q$d = step;
            sh$d = ext_step$y;
            acc$d = 32'h0;
        end
        if (run) begin
            sh$d = sh$q << 32'h1;
            if (x0_bit & last) begin
                acc$d = acc$q - sh$q;
            end
            if (x0_bit & ~last) begin
                acc$d = acc$q + sh$q;
            end
        end
        line_a$x = step_q$q;
        line_b$x = ext_v0$y - acc$q;
        a = line_a$y;
        b = line_b$y;
    end
    
endmodule // se_cmd$attr_g


module se_cmd$attr_g$acc(d,q,clock);
    
    // Module arguments
    input wire  [49:0] d;
    output reg  [49:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 50'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_g$acc


module se_cmd$attr_g$ext_step(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [49:0] y;
    
    // Constant declarations
    localparam  msb = 8'h23;
    localparam  ext = 50'h3fff000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 50'h3ffffffffffff);
        if (x[msb]) begin
            y = ((x) & 50'h3ffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_g$ext_step


module se_cmd$attr_g$ext_v0(x,y);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  [49:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1f;
    localparam  ext = 50'h3ffff00000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 50'h3ffffffffffff);
        if (x[msb]) begin
            y = ((x) & 50'h3ffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_g$ext_v0


module se_cmd$attr_g$line_a(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [36:0] y;
    
    // Constant declarations
    localparam  frac = 8'h10;
    localparam  half = 89'h200000;
    localparam  s = 8'h16;
    
    // Stub signals
    reg  [35:0] widen$x;
    wire  [88:0] widen$y;
    
    // Sub module instances
    se_cmd$attr_g$line_a$widen widen(
        .x(widen$x),
        .y(widen$y)
    );
    
    // Update code
    always @(*) begin
        widen$x = x;
        y = ((((widen$y << frac) + half) >> s) & 37'h1fffffffff);
    end
    
endmodule // se_cmd$attr_g$line_a


module se_cmd$attr_g$line_a$widen(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [88:0] y;
    
    // Constant declarations
    localparam  msb = 8'h23;
    localparam  ext = 89'h1fffffffffffff000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 89'h1ffffffffffffffffffffff);
        if (x[msb]) begin
            y = ((x) & 89'h1ffffffffffffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_g$line_a$widen


module se_cmd$attr_g$line_b(x,y);
    
    // Module arguments
    input wire  [49:0] x;
    output reg  [36:0] y;
    
    // Constant declarations
    localparam  frac = 8'h10;
    localparam  half = 103'h200000;
    localparam  s = 8'h16;
    
    // Stub signals
    reg  [49:0] widen$x;
    wire  [102:0] widen$y;
    
    // Sub module instances
    se_cmd$attr_g$line_b$widen widen(
        .x(widen$x),
        .y(widen$y)
    );
    
    // Update code
    always @(*) begin
        widen$x = x;
        y = ((((widen$y << frac) + half) >> s) & 37'h1fffffffff);
    end
    
endmodule // se_cmd$attr_g$line_b


module se_cmd$attr_g$line_b$widen(x,y);
    
    // Module arguments
    input wire  [49:0] x;
    output reg  [102:0] y;
    
    // Constant declarations
    localparam  msb = 8'h31;
    localparam  ext = 103'h7ffffffffffffc000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 103'h7fffffffffffffffffffffffff);
        if (x[msb]) begin
            y = ((x) & 103'h7fffffffffffffffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_g$line_b$widen


module se_cmd$attr_g$sh(d,q,clock);
    
    // Module arguments
    input wire  [49:0] d;
    output reg  [49:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 50'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_g$sh


module se_cmd$attr_g$step_q(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_g$step_q


module se_cmd$attr_g$v0_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_g$v0_q


module se_cmd$attr_r(clock,load,v0,step,run,x0_bit,last,a,b);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  [31:0] v0;
    input wire  [35:0] step;
    input wire  run;
    input wire  x0_bit;
    input wire  last;
    output reg  [36:0] a;
    output reg  [36:0] b;
    
    // Stub signals
    reg  [31:0] v0_q$d;
    wire  [31:0] v0_q$q;
    reg  v0_q$clock;
    reg  [35:0] step_q$d;
    wire  [35:0] step_q$q;
    reg  step_q$clock;
    reg  [49:0] sh$d;
    wire  [49:0] sh$q;
    reg  sh$clock;
    reg  [49:0] acc$d;
    wire  [49:0] acc$q;
    reg  acc$clock;
    reg  [35:0] ext_step$x;
    wire  [49:0] ext_step$y;
    reg  [31:0] ext_v0$x;
    wire  [49:0] ext_v0$y;
    reg  [35:0] line_a$x;
    wire  [36:0] line_a$y;
    reg  [49:0] line_b$x;
    wire  [36:0] line_b$y;
    
    // Sub module instances
    se_cmd$attr_r$v0_q v0_q(
        .d(v0_q$d),
        .q(v0_q$q),
        .clock(v0_q$clock)
    );
    se_cmd$attr_r$step_q step_q(
        .d(step_q$d),
        .q(step_q$q),
        .clock(step_q$clock)
    );
    se_cmd$attr_r$sh sh(
        .d(sh$d),
        .q(sh$q),
        .clock(sh$clock)
    );
    se_cmd$attr_r$acc acc(
        .d(acc$d),
        .q(acc$q),
        .clock(acc$clock)
    );
    se_cmd$attr_r$ext_step ext_step(
        .x(ext_step$x),
        .y(ext_step$y)
    );
    se_cmd$attr_r$ext_v0 ext_v0(
        .x(ext_v0$x),
        .y(ext_v0$y)
    );
    se_cmd$attr_r$line_a line_a(
        .x(line_a$x),
        .y(line_a$y)
    );
    se_cmd$attr_r$line_b line_b(
        .x(line_b$x),
        .y(line_b$y)
    );
    
    // Update code
    always @(*) begin
        v0_q$clock = clock;
        step_q$clock = clock;
        sh$clock = clock;
        acc$clock = clock;
        v0_q$d = v0_q$q;
        step_q$d = step_q$q;
        sh$d = sh$q;
        acc$d = acc$q;
        ext_step$x = step;
        ext_v0$x = v0_q$q;
        if (load) begin
            v0_q$d = v0;
            step_q$d = step;
            sh$d = ext_step$y;
            acc$d = 32'h0;
        end
        if (run) begin
            sh$d = sh$q << 32'h1;
            if (x0_bit & last) begin
                acc$d = acc$q - sh$q;
            end
            if (x0_bit & ~last) begin
                acc$d = acc$q + sh$q;
            end
        end
        line_a$x = step_q$q;
        line_b$x = ext_v0$y - acc$q;
        a = line_a$y;
        b = line_b$y;
    end
    
endmodule // se_cmd$attr_r


module se_cmd$attr_r$acc(d,q,clock);
    
    // Module arguments
    input wire  [49:0] d;
    output reg  [49:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 50'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_r$acc


module se_cmd$attr_r$ext_step(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [49:0] y;
    
    // Constant declarations
    localparam  msb = 8'h23;
    localparam  ext = 50'h3fff000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 50'h3ffffffffffff);
        if (x[msb]) begin
            y = ((x) & 50'h3ffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_r$ext_step


module se_cmd$attr_r$ext_v0(x,y);
    
    // Module arguments
    input wire  [31:0] x;
    output reg  [49:0] y;
    
    // Constant declarations
    localparam  msb = 8'h1f;
    localparam  ext = 50'h3ffff00000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 50'h3ffffffffffff);
        if (x[msb]) begin
            y = ((x) & 50'h3ffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_r$ext_v0


module se_cmd$attr_r$line_a(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [36:0] y;
    
    // Constant declarations
    localparam  frac = 8'h10;
    localparam  half = 89'h200000;
    localparam  s = 8'h16;
    
    // Stub signals
    reg  [35:0] widen$x;
    wire  [88:0] widen$y;
    
    // Sub module instances
    se_cmd$attr_r$line_a$widen widen(
        .x(widen$x),
        .y(widen$y)
    );
    
    // Update code
    always @(*) begin
        widen$x = x;
        y = ((((widen$y << frac) + half) >> s) & 37'h1fffffffff);
    end
    
endmodule // se_cmd$attr_r$line_a


module se_cmd$attr_r$line_a$widen(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [88:0] y;
    
    // Constant declarations
    localparam  msb = 8'h23;
    localparam  ext = 89'h1fffffffffffff000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 89'h1ffffffffffffffffffffff);
        if (x[msb]) begin
            y = ((x) & 89'h1ffffffffffffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_r$line_a$widen


module se_cmd$attr_r$line_b(x,y);
    
    // Module arguments
    input wire  [49:0] x;
    output reg  [36:0] y;
    
    // Constant declarations
    localparam  frac = 8'h10;
    localparam  half = 103'h200000;
    localparam  s = 8'h16;
    
    // Stub signals
    reg  [49:0] widen$x;
    wire  [102:0] widen$y;
    
    // Sub module instances
    se_cmd$attr_r$line_b$widen widen(
        .x(widen$x),
        .y(widen$y)
    );
    
    // Update code
    always @(*) begin
        widen$x = x;
        y = ((((widen$y << frac) + half) >> s) & 37'h1fffffffff);
    end
    
endmodule // se_cmd$attr_r$line_b


module se_cmd$attr_r$line_b$widen(x,y);
    
    // Module arguments
    input wire  [49:0] x;
    output reg  [102:0] y;
    
    // Constant declarations
    localparam  msb = 8'h31;
    localparam  ext = 103'h7ffffffffffffc000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 103'h7fffffffffffffffffffffffff);
        if (x[msb]) begin
            y = ((x) & 103'h7fffffffffffffffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_r$line_b$widen


module se_cmd$attr_r$sh(d,q,clock);
    
    // Module arguments
    input wire  [49:0] d;
    output reg  [49:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 50'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_r$sh


module se_cmd$attr_r$step_q(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_r$step_q


module se_cmd$attr_r$v0_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_r$v0_q


module se_cmd$attr_z(clock,load,v0,step,run,x0_bit,last,a,b);
    
    // Module arguments
    input wire  clock;
    input wire  load;
    input wire  [35:0] v0;
    input wire  [39:0] step;
    input wire  run;
    input wire  x0_bit;
    input wire  last;
    output reg  [44:0] a;
    output reg  [44:0] b;
    
    // Stub signals
    reg  [35:0] v0_q$d;
    wire  [35:0] v0_q$q;
    reg  v0_q$clock;
    reg  [39:0] step_q$d;
    wire  [39:0] step_q$q;
    reg  step_q$clock;
    reg  [53:0] sh$d;
    wire  [53:0] sh$q;
    reg  sh$clock;
    reg  [53:0] acc$d;
    wire  [53:0] acc$q;
    reg  acc$clock;
    reg  [39:0] ext_step$x;
    wire  [53:0] ext_step$y;
    reg  [35:0] ext_v0$x;
    wire  [53:0] ext_v0$y;
    reg  [39:0] line_a$x;
    wire  [44:0] line_a$y;
    reg  [53:0] line_b$x;
    wire  [44:0] line_b$y;
    
    // Sub module instances
    se_cmd$attr_z$v0_q v0_q(
        .d(v0_q$d),
        .q(v0_q$q),
        .clock(v0_q$clock)
    );
    se_cmd$attr_z$step_q step_q(
        .d(step_q$d),
        .q(step_q$q),
        .clock(step_q$clock)
    );
    se_cmd$attr_z$sh sh(
        .d(sh$d),
        .q(sh$q),
        .clock(sh$clock)
    );
    se_cmd$attr_z$acc acc(
        .d(acc$d),
        .q(acc$q),
        .clock(acc$clock)
    );
    se_cmd$attr_z$ext_step ext_step(
        .x(ext_step$x),
        .y(ext_step$y)
    );
    se_cmd$attr_z$ext_v0 ext_v0(
        .x(ext_v0$x),
        .y(ext_v0$y)
    );
    se_cmd$attr_z$line_a line_a(
        .x(line_a$x),
        .y(line_a$y)
    );
    se_cmd$attr_z$line_b line_b(
        .x(line_b$x),
        .y(line_b$y)
    );
    
    // Update code
    always @(*) begin
        v0_q$clock = clock;
        step_q$clock = clock;
        sh$clock = clock;
        acc$clock = clock;
        v0_q$d = v0_q$q;
        step_q$d = step_q$q;
        sh$d = sh$q;
        acc$d = acc$q;
        ext_step$x = step;
        ext_v0$x = v0_q$q;
        if (load) begin
            v0_q$d = v0;
            step_q$d = step;
            sh$d = ext_step$y;
            acc$d = 32'h0;
        end
        if (run) begin
            sh$d = sh$q << 32'h1;
            if (x0_bit & last) begin
                acc$d = acc$q - sh$q;
            end
            if (x0_bit & ~last) begin
                acc$d = acc$q + sh$q;
            end
        end
        line_a$x = step_q$q;
        line_b$x = ext_v0$y - acc$q;
        a = line_a$y;
        b = line_b$y;
    end
    
endmodule // se_cmd$attr_z


module se_cmd$attr_z$acc(d,q,clock);
    
    // Module arguments
    input wire  [53:0] d;
    output reg  [53:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 54'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_z$acc


module se_cmd$attr_z$ext_step(x,y);
    
    // Module arguments
    input wire  [39:0] x;
    output reg  [53:0] y;
    
    // Constant declarations
    localparam  msb = 8'h27;
    localparam  ext = 54'h3fff0000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 54'h3fffffffffffff);
        if (x[msb]) begin
            y = ((x) & 54'h3fffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_z$ext_step


module se_cmd$attr_z$ext_v0(x,y);
    
    // Module arguments
    input wire  [35:0] x;
    output reg  [53:0] y;
    
    // Constant declarations
    localparam  msb = 8'h23;
    localparam  ext = 54'h3ffff000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 54'h3fffffffffffff);
        if (x[msb]) begin
            y = ((x) & 54'h3fffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_z$ext_v0


module se_cmd$attr_z$line_a(x,y);
    
    // Module arguments
    input wire  [39:0] x;
    output reg  [44:0] y;
    
    // Constant declarations
    localparam  frac = 8'h10;
    localparam  half = 101'h20000;
    localparam  s = 8'h12;
    
    // Stub signals
    reg  [39:0] widen$x;
    wire  [100:0] widen$y;
    
    // Sub module instances
    se_cmd$attr_z$line_a$widen widen(
        .x(widen$x),
        .y(widen$y)
    );
    
    // Update code
    always @(*) begin
        widen$x = x;
        y = ((((widen$y << frac) + half) >> s) & 45'h1fffffffffff);
    end
    
endmodule // se_cmd$attr_z$line_a


module se_cmd$attr_z$line_a$widen(x,y);
    
    // Module arguments
    input wire  [39:0] x;
    output reg  [100:0] y;
    
    // Constant declarations
    localparam  msb = 8'h27;
    localparam  ext = 101'h1fffffffffffffff0000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 101'h1fffffffffffffffffffffffff);
        if (x[msb]) begin
            y = ((x) & 101'h1fffffffffffffffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_z$line_a$widen


module se_cmd$attr_z$line_b(x,y);
    
    // Module arguments
    input wire  [53:0] x;
    output reg  [44:0] y;
    
    // Constant declarations
    localparam  frac = 8'h10;
    localparam  half = 115'h20000;
    localparam  s = 8'h12;
    
    // Stub signals
    reg  [53:0] widen$x;
    wire  [114:0] widen$y;
    
    // Sub module instances
    se_cmd$attr_z$line_b$widen widen(
        .x(widen$x),
        .y(widen$y)
    );
    
    // Update code
    always @(*) begin
        widen$x = x;
        y = ((((widen$y << frac) + half) >> s) & 45'h1fffffffffff);
    end
    
endmodule // se_cmd$attr_z$line_b


module se_cmd$attr_z$line_b$widen(x,y);
    
    // Module arguments
    input wire  [53:0] x;
    output reg  [114:0] y;
    
    // Constant declarations
    localparam  msb = 8'h35;
    localparam  ext = 115'h7ffffffffffffffc0000000000000;
    
    // Update code
    always @(*) begin
        y = ((x) & 115'h7ffffffffffffffffffffffffffff);
        if (x[msb]) begin
            y = ((x) & 115'h7ffffffffffffffffffffffffffff) | ext;
        end
    end
    
endmodule // se_cmd$attr_z$line_b$widen


module se_cmd$attr_z$sh(d,q,clock);
    
    // Module arguments
    input wire  [53:0] d;
    output reg  [53:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 54'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_z$sh


module se_cmd$attr_z$step_q(d,q,clock);
    
    // Module arguments
    input wire  [39:0] d;
    output reg  [39:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 40'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_z$step_q


module se_cmd$attr_z$v0_q(d,q,clock);
    
    // Module arguments
    input wire  [35:0] d;
    output reg  [35:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 36'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$attr_z$v0_q


module se_cmd$busy(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$busy


module se_cmd$cxl(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$cxl


module se_cmd$cxr(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$cxr


module se_cmd$k(d,q,clock);
    
    // Module arguments
    input wire  [4:0] d;
    output reg  [4:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 5'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$k


module se_cmd$last_y(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$last_y


module se_cmd$prev_y(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$prev_y


module se_cmd$since(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$since


module se_cmd$started(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$started


module se_cmd$x0s(d,q,clock);
    
    // Module arguments
    input wire  [12:0] d;
    output reg  [12:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 13'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$x0s


module se_cmd$xl_neg(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // se_cmd$xl_neg


module se_cmd$xr_neg(x,neg);
    
    // Module arguments
    input wire  [12:0] x;
    output reg  neg;
    
    // Constant declarations
    localparam  half = 13'b1000000000000;
    
    // Update code
    always @(*) begin
        neg = x >= half;
    end
    
endmodule // se_cmd$xr_neg


module se_cmd$y(d,q,clock);
    
    // Module arguments
    input wire  [9:0] d;
    output reg  [9:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 10'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // se_cmd$y
