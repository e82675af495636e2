

module divider(clock,inp_valid,inp_ready,hold,inp_n,inp_d,out_valid,out_ready,out_q,out_r);
    
    // Module arguments
    input wire  clock;
    input wire  inp_valid;
    output reg  inp_ready;
    input wire  hold;
    input wire  [57:0] inp_n;
    input wire  [33:0] inp_d;
    output reg  out_valid;
    input wire  out_ready;
    output reg  [25:0] out_q;
    output reg  [33:0] out_r;
    
    // Constant declarations
    localparam  n_msb = 8'h39;
    localparam  qm = 8'h19;
    
    // Stub signals
    reg  stages$0$clock;
    reg  stages$0$enable;
    reg  stages$0$valid_in;
    reg  [33:0] stages$0$p_in;
    reg  [24:0] stages$0$x_in;
    reg  [33:0] stages$0$d_in;
    reg  stages$0$neg_in;
    wire  stages$0$valid;
    wire  [33:0] stages$0$p;
    wire  [24:0] stages$0$x;
    wire  [33:0] stages$0$d;
    wire  stages$0$neg;
    reg  stages$1$clock;
    reg  stages$1$enable;
    reg  stages$1$valid_in;
    reg  [33:0] stages$1$p_in;
    reg  [24:0] stages$1$x_in;
    reg  [33:0] stages$1$d_in;
    reg  stages$1$neg_in;
    wire  stages$1$valid;
    wire  [33:0] stages$1$p;
    wire  [24:0] stages$1$x;
    wire  [33:0] stages$1$d;
    wire  stages$1$neg;
    reg  stages$2$clock;
    reg  stages$2$enable;
    reg  stages$2$valid_in;
    reg  [33:0] stages$2$p_in;
    reg  [24:0] stages$2$x_in;
    reg  [33:0] stages$2$d_in;
    reg  stages$2$neg_in;
    wire  stages$2$valid;
    wire  [33:0] stages$2$p;
    wire  [24:0] stages$2$x;
    wire  [33:0] stages$2$d;
    wire  stages$2$neg;
    reg  stages$3$clock;
    reg  stages$3$enable;
    reg  stages$3$valid_in;
    reg  [33:0] stages$3$p_in;
    reg  [24:0] stages$3$x_in;
    reg  [33:0] stages$3$d_in;
    reg  stages$3$neg_in;
    wire  stages$3$valid;
    wire  [33:0] stages$3$p;
    wire  [24:0] stages$3$x;
    wire  [33:0] stages$3$d;
    wire  stages$3$neg;
    reg  stages$4$clock;
    reg  stages$4$enable;
    reg  stages$4$valid_in;
    reg  [33:0] stages$4$p_in;
    reg  [24:0] stages$4$x_in;
    reg  [33:0] stages$4$d_in;
    reg  stages$4$neg_in;
    wire  stages$4$valid;
    wire  [33:0] stages$4$p;
    wire  [24:0] stages$4$x;
    wire  [33:0] stages$4$d;
    wire  stages$4$neg;
    
    // Local signals
    reg  advance;
    reg  [57:0] m;
    reg  [24:0] last_x;
    
    // Sub module instances
    divider$stages$0 stages$0(
        .clock(stages$0$clock),
        .enable(stages$0$enable),
        .valid_in(stages$0$valid_in),
        .p_in(stages$0$p_in),
        .x_in(stages$0$x_in),
        .d_in(stages$0$d_in),
        .neg_in(stages$0$neg_in),
        .valid(stages$0$valid),
        .p(stages$0$p),
        .x(stages$0$x),
        .d(stages$0$d),
        .neg(stages$0$neg)
    );
    divider$stages$1 stages$1(
        .clock(stages$1$clock),
        .enable(stages$1$enable),
        .valid_in(stages$1$valid_in),
        .p_in(stages$1$p_in),
        .x_in(stages$1$x_in),
        .d_in(stages$1$d_in),
        .neg_in(stages$1$neg_in),
        .valid(stages$1$valid),
        .p(stages$1$p),
        .x(stages$1$x),
        .d(stages$1$d),
        .neg(stages$1$neg)
    );
    divider$stages$2 stages$2(
        .clock(stages$2$clock),
        .enable(stages$2$enable),
        .valid_in(stages$2$valid_in),
        .p_in(stages$2$p_in),
        .x_in(stages$2$x_in),
        .d_in(stages$2$d_in),
        .neg_in(stages$2$neg_in),
        .valid(stages$2$valid),
        .p(stages$2$p),
        .x(stages$2$x),
        .d(stages$2$d),
        .neg(stages$2$neg)
    );
    divider$stages$3 stages$3(
        .clock(stages$3$clock),
        .enable(stages$3$enable),
        .valid_in(stages$3$valid_in),
        .p_in(stages$3$p_in),
        .x_in(stages$3$x_in),
        .d_in(stages$3$d_in),
        .neg_in(stages$3$neg_in),
        .valid(stages$3$valid),
        .p(stages$3$p),
        .x(stages$3$x),
        .d(stages$3$d),
        .neg(stages$3$neg)
    );
    divider$stages$4 stages$4(
        .clock(stages$4$clock),
        .enable(stages$4$enable),
        .valid_in(stages$4$valid_in),
        .p_in(stages$4$p_in),
        .x_in(stages$4$x_in),
        .d_in(stages$4$d_in),
        .neg_in(stages$4$neg_in),
        .valid(stages$4$valid),
        .p(stages$4$p),
        .x(stages$4$x),
        .d(stages$4$d),
        .neg(stages$4$neg)
    );
    
    // Update code
    always @(*) begin
        advance = ~hold & (~stages$4$valid | out_ready);
        out_valid = stages$4$valid;
        last_x = stages$4$x;
        out_r = stages$4$p;
        if (stages$4$neg) begin
            out_r = stages$4$d - stages$4$p - 32'h1;
        end
        out_q = ((last_x) & 26'h3ffffff);
        if (stages$4$neg) begin
            out_q = ~((last_x) & 26'h3ffffff);
        end
        stages$0$clock = clock;
        stages$0$enable = advance;
        stages$1$clock = clock;
        stages$1$enable = advance;
        stages$2$clock = clock;
        stages$2$enable = advance;
        stages$3$clock = clock;
        stages$3$enable = advance;
        stages$4$clock = clock;
        stages$4$enable = advance;
        inp_ready = advance;
        m = inp_n;
        if (inp_n[n_msb]) begin
            m = ~inp_n;
        end
        stages$0$valid_in = inp_valid;
        stages$0$p_in = ((m >> qm) & 34'h3ffffffff);
        stages$0$x_in = m[(32'h0)+:(25)];
        stages$0$d_in = inp_d;
        stages$0$neg_in = inp_n[n_msb];
        stages$1$valid_in = stages$0$valid;
        stages$1$p_in = stages$0$p;
        stages$1$x_in = stages$0$x;
        stages$1$d_in = stages$0$d;
        stages$1$neg_in = stages$0$neg;
        stages$2$valid_in = stages$1$valid;
        stages$2$p_in = stages$1$p;
        stages$2$x_in = stages$1$x;
        stages$2$d_in = stages$1$d;
        stages$2$neg_in = stages$1$neg;
        stages$3$valid_in = stages$2$valid;
        stages$3$p_in = stages$2$p;
        stages$3$x_in = stages$2$x;
        stages$3$d_in = stages$2$d;
        stages$3$neg_in = stages$2$neg;
        stages$4$valid_in = stages$3$valid;
        stages$4$p_in = stages$3$p;
        stages$4$x_in = stages$3$x;
        stages$4$d_in = stages$3$d;
        stages$4$neg_in = stages$3$neg;
    end
    
endmodule // divider


module divider$stages$0(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [34:0] tp$3;
    reg  [34:0] tp$4;
    reg  [34:0] tp$5;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [24:0] tx$3;
    reg  [24:0] tx$4;
    reg  [24:0] tx$5;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] t$2;
    reg  [34:0] t$3;
    reg  [34:0] t$4;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] diff$2;
    reg  [34:0] diff$3;
    reg  [34:0] diff$4;
    reg  [34:0] d1;
    
    // Sub module instances
    divider$stages$0$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$0$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$0$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$0$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$0$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        t$2 = tp$2 << 32'h1;
        if (tx$2[x_msb]) begin
            t$2 = (tp$2 << 32'h1) | 32'h1;
        end
        diff$2 = t$2 - d1;
        if (diff$2[borrow]) begin
            tp$3 = t$2;
            tx$3 = tx$2 << 32'h1;
        end
        else begin
            tp$3 = diff$2;
            tx$3 = (tx$2 << 32'h1) | 32'h1;
        end
        t$3 = tp$3 << 32'h1;
        if (tx$3[x_msb]) begin
            t$3 = (tp$3 << 32'h1) | 32'h1;
        end
        diff$3 = t$3 - d1;
        if (diff$3[borrow]) begin
            tp$4 = t$3;
            tx$4 = tx$3 << 32'h1;
        end
        else begin
            tp$4 = diff$3;
            tx$4 = (tx$3 << 32'h1) | 32'h1;
        end
        t$4 = tp$4 << 32'h1;
        if (tx$4[x_msb]) begin
            t$4 = (tp$4 << 32'h1) | 32'h1;
        end
        diff$4 = t$4 - d1;
        if (diff$4[borrow]) begin
            tp$5 = t$4;
            tx$5 = tx$4 << 32'h1;
        end
        else begin
            tp$5 = diff$4;
            tx$5 = (tx$4 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$5[(32'h0)+:(34)];
            x_r$d = tx$5;
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // divider$stages$0


module divider$stages$0$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$0$d_r


module divider$stages$0$neg_r(d,q,clock);
    
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
          
endmodule // divider$stages$0$neg_r


module divider$stages$0$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$0$p_r


module divider$stages$0$valid_r(d,q,clock);
    
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
          
endmodule // divider$stages$0$valid_r


module divider$stages$0$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$0$x_r


module divider$stages$1(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [34:0] tp$3;
    reg  [34:0] tp$4;
    reg  [34:0] tp$5;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [24:0] tx$3;
    reg  [24:0] tx$4;
    reg  [24:0] tx$5;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] t$2;
    reg  [34:0] t$3;
    reg  [34:0] t$4;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] diff$2;
    reg  [34:0] diff$3;
    reg  [34:0] diff$4;
    reg  [34:0] d1;
    
    // Sub module instances
    divider$stages$1$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$1$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$1$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$1$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$1$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        t$2 = tp$2 << 32'h1;
        if (tx$2[x_msb]) begin
            t$2 = (tp$2 << 32'h1) | 32'h1;
        end
        diff$2 = t$2 - d1;
        if (diff$2[borrow]) begin
            tp$3 = t$2;
            tx$3 = tx$2 << 32'h1;
        end
        else begin
            tp$3 = diff$2;
            tx$3 = (tx$2 << 32'h1) | 32'h1;
        end
        t$3 = tp$3 << 32'h1;
        if (tx$3[x_msb]) begin
            t$3 = (tp$3 << 32'h1) | 32'h1;
        end
        diff$3 = t$3 - d1;
        if (diff$3[borrow]) begin
            tp$4 = t$3;
            tx$4 = tx$3 << 32'h1;
        end
        else begin
            tp$4 = diff$3;
            tx$4 = (tx$3 << 32'h1) | 32'h1;
        end
        t$4 = tp$4 << 32'h1;
        if (tx$4[x_msb]) begin
            t$4 = (tp$4 << 32'h1) | 32'h1;
        end
        diff$4 = t$4 - d1;
        if (diff$4[borrow]) begin
            tp$5 = t$4;
            tx$5 = tx$4 << 32'h1;
        end
        else begin
            tp$5 = diff$4;
            tx$5 = (tx$4 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$5[(32'h0)+:(34)];
            x_r$d = tx$5;
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // divider$stages$1


module divider$stages$1$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$1$d_r


module divider$stages$1$neg_r(d,q,clock);
    
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
          
endmodule // divider$stages$1$neg_r


module divider$stages$1$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$1$p_r


module divider$stages$1$valid_r(d,q,clock);
    
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
          
endmodule // divider$stages$1$valid_r


module divider$stages$1$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$1$x_r


module divider$stages$2(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [34:0] tp$3;
    reg  [34:0] tp$4;
    reg  [34:0] tp$5;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [24:0] tx$3;
    reg  [24:0] tx$4;
    reg  [24:0] tx$5;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] t$2;
    reg  [34:0] t$3;
    reg  [34:0] t$4;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] diff$2;
    reg  [34:0] diff$3;
    reg  [34:0] diff$4;
    reg  [34:0] d1;
    
    // Sub module instances
    divider$stages$2$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$2$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$2$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$2$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$2$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        t$2 = tp$2 << 32'h1;
        if (tx$2[x_msb]) begin
            t$2 = (tp$2 << 32'h1) | 32'h1;
        end
        diff$2 = t$2 - d1;
        if (diff$2[borrow]) begin
            tp$3 = t$2;
            tx$3 = tx$2 << 32'h1;
        end
        else begin
            tp$3 = diff$2;
            tx$3 = (tx$2 << 32'h1) | 32'h1;
        end
        t$3 = tp$3 << 32'h1;
        if (tx$3[x_msb]) begin
            t$3 = (tp$3 << 32'h1) | 32'h1;
        end
        diff$3 = t$3 - d1;
        if (diff$3[borrow]) begin
            tp$4 = t$3;
            tx$4 = tx$3 << 32'h1;
        end
        else begin
            tp$4 = diff$3;
            tx$4 = (tx$3 << 32'h1) | 32'h1;
        end
        t$4 = tp$4 << 32'h1;
        if (tx$4[x_msb]) begin
            t$4 = (tp$4 << 32'h1) | 32'h1;
        end
        diff$4 = t$4 - d1;
        if (diff$4[borrow]) begin
            tp$5 = t$4;
            tx$5 = tx$4 << 32'h1;
        end
        else begin
            tp$5 = diff$4;
            tx$5 = (tx$4 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$5[(32'h0)+:(34)];
            x_r$d = tx$5;
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // divider$stages$2


module divider$stages$2$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$2$d_r


module divider$stages$2$neg_r(d,q,clock);
    
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
          
endmodule // divider$stages$2$neg_r


module divider$stages$2$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$2$p_r


module divider$stages$2$valid_r(d,q,clock);
    
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
          
endmodule // divider$stages$2$valid_r


module divider$stages$2$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$2$x_r


module divider$stages$3(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [34:0] tp$3;
    reg  [34:0] tp$4;
    reg  [34:0] tp$5;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [24:0] tx$3;
    reg  [24:0] tx$4;
    reg  [24:0] tx$5;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] t$2;
    reg  [34:0] t$3;
    reg  [34:0] t$4;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] diff$2;
    reg  [34:0] diff$3;
    reg  [34:0] diff$4;
    reg  [34:0] d1;
    
    // Sub module instances
    divider$stages$3$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$3$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$3$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$3$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$3$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        t$2 = tp$2 << 32'h1;
        if (tx$2[x_msb]) begin
            t$2 = (tp$2 << 32'h1) | 32'h1;
        end
        diff$2 = t$2 - d1;
        if (diff$2[borrow]) begin
            tp$3 = t$2;
            tx$3 = tx$2 << 32'h1;
        end
        else begin
            tp$3 = diff$2;
            tx$3 = (tx$2 << 32'h1) | 32'h1;
        end
        t$3 = tp$3 << 32'h1;
        if (tx$3[x_msb]) begin
            t$3 = (tp$3 << 32'h1) | 32'h1;
        end
        diff$3 = t$3 - d1;
        if (diff$3[borrow]) begin
            tp$4 = t$3;
            tx$4 = tx$3 << 32'h1;
        end
        else begin
            tp$4 = diff$3;
            tx$4 = (tx$3 << 32'h1) | 32'h1;
        end
        t$4 = tp$4 << 32'h1;
        if (tx$4[x_msb]) begin
            t$4 = (tp$4 << 32'h1) | 32'h1;
        end
        diff$4 = t$4 - d1;
        if (diff$4[borrow]) begin
            tp$5 = t$4;
            tx$5 = tx$4 << 32'h1;
        end
        else begin
            tp$5 = diff$4;
            tx$5 = (tx$4 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$5[(32'h0)+:(34)];
            x_r$d = tx$5;
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // divider$stages$3


module divider$stages$3$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$3$d_r


module divider$stages$3$neg_r(d,q,clock);
    
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
          
endmodule // divider$stages$3$neg_r


module divider$stages$3$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$3$p_r


module divider$stages$3$valid_r(d,q,clock);
    
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
          
endmodule // divider$stages$3$valid_r


module divider$stages$3$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$3$x_r


module divider$stages$4(clock,enable,valid_in,p_in,x_in,d_in,neg_in,valid,p,x,d,neg);
    
    // Module arguments
    input wire  clock;
    input wire  enable;
    input wire  valid_in;
    input wire  [33:0] p_in;
    input wire  [24:0] x_in;
    input wire  [33:0] d_in;
    input wire  neg_in;
    output reg  valid;
    output reg  [33:0] p;
    output reg  [24:0] x;
    output reg  [33:0] d;
    output reg  neg;
    
    // Constant declarations
    localparam  borrow = 8'h22;
    localparam  x_msb = 8'h18;
    
    // Stub signals
    reg  valid_r$d;
    wire  valid_r$q;
    reg  valid_r$clock;
    reg  [33:0] p_r$d;
    wire  [33:0] p_r$q;
    reg  p_r$clock;
    reg  [24:0] x_r$d;
    wire  [24:0] x_r$q;
    reg  x_r$clock;
    reg  [33:0] d_r$d;
    wire  [33:0] d_r$q;
    reg  d_r$clock;
    reg  neg_r$d;
    wire  neg_r$q;
    reg  neg_r$clock;
    
    // Local signals
    reg  [34:0] tp$0;
    reg  [34:0] tp$1;
    reg  [34:0] tp$2;
    reg  [34:0] tp$3;
    reg  [34:0] tp$4;
    reg  [34:0] tp$5;
    reg  [24:0] tx$0;
    reg  [24:0] tx$1;
    reg  [24:0] tx$2;
    reg  [24:0] tx$3;
    reg  [24:0] tx$4;
    reg  [24:0] tx$5;
    reg  [34:0] t$0;
    reg  [34:0] t$1;
    reg  [34:0] t$2;
    reg  [34:0] t$3;
    reg  [34:0] t$4;
    reg  [34:0] diff$0;
    reg  [34:0] diff$1;
    reg  [34:0] diff$2;
    reg  [34:0] diff$3;
    reg  [34:0] diff$4;
    reg  [34:0] d1;
    
    // Sub module instances
    divider$stages$4$valid_r valid_r(
        .d(valid_r$d),
        .q(valid_r$q),
        .clock(valid_r$clock)
    );
    divider$stages$4$p_r p_r(
        .d(p_r$d),
        .q(p_r$q),
        .clock(p_r$clock)
    );
    divider$stages$4$x_r x_r(
        .d(x_r$d),
        .q(x_r$q),
        .clock(x_r$clock)
    );
    divider$stages$4$d_r d_r(
        .d(d_r$d),
        .q(d_r$q),
        .clock(d_r$clock)
    );
    divider$stages$4$neg_r neg_r(
        .d(neg_r$d),
        .q(neg_r$q),
        .clock(neg_r$clock)
    );
    
    // Update code
    always @(*) begin
        valid_r$clock = clock;
        p_r$clock = clock;
        x_r$clock = clock;
        d_r$clock = clock;
        neg_r$clock = clock;
        valid_r$d = valid_r$q;
        p_r$d = p_r$q;
        x_r$d = x_r$q;
        d_r$d = d_r$q;
        neg_r$d = neg_r$q;
        d1 = ((d_in) & 35'h7ffffffff);
        tp$0 = ((p_in) & 35'h7ffffffff);
        tx$0 = x_in;
        t$0 = tp$0 << 32'h1;
        if (tx$0[x_msb]) begin
            t$0 = (tp$0 << 32'h1) | 32'h1;
        end
        diff$0 = t$0 - d1;
        if (diff$0[borrow]) begin
            tp$1 = t$0;
            tx$1 = tx$0 << 32'h1;
        end
        else begin
            tp$1 = diff$0;
            tx$1 = (tx$0 << 32'h1) | 32'h1;
        end
        t$1 = tp$1 << 32'h1;
        if (tx$1[x_msb]) begin
            t$1 = (tp$1 << 32'h1) | 32'h1;
        end
        diff$1 = t$1 - d1;
        if (diff$1[borrow]) begin
            tp$2 = t$1;
            tx$2 = tx$1 << 32'h1;
        end
        else begin
            tp$2 = diff$1;
            tx$2 = (tx$1 << 32'h1) | 32'h1;
        end
        t$2 = tp$2 << 32'h1;
        if (tx$2[x_msb]) begin
            t$2 = (tp$2 << 32'h1) | 32'h1;
        end
        diff$2 = t$2 - d1;
        if (diff$2[borrow]) begin
            tp$3 = t$2;
            tx$3 = tx$2 << 32'h1;
        end
        else begin
            tp$3 = diff$2;
            tx$3 = (tx$2 << 32'h1) | 32'h1;
        end
        t$3 = tp$3 << 32'h1;
        if (tx$3[x_msb]) begin
            t$3 = (tp$3 << 32'h1) | 32'h1;
        end
        diff$3 = t$3 - d1;
        if (diff$3[borrow]) begin
            tp$4 = t$3;
            tx$4 = tx$3 << 32'h1;
        end
        else begin
            tp$4 = diff$3;
            tx$4 = (tx$3 << 32'h1) | 32'h1;
        end
        t$4 = tp$4 << 32'h1;
        if (tx$4[x_msb]) begin
            t$4 = (tp$4 << 32'h1) | 32'h1;
        end
        diff$4 = t$4 - d1;
        if (diff$4[borrow]) begin
            tp$5 = t$4;
            tx$5 = tx$4 << 32'h1;
        end
        else begin
            tp$5 = diff$4;
            tx$5 = (tx$4 << 32'h1) | 32'h1;
        end
        if (enable) begin
            valid_r$d = valid_in;
            p_r$d = tp$5[(32'h0)+:(34)];
            x_r$d = tx$5;
            d_r$d = d_in;
            neg_r$d = neg_in;
        end
        valid = valid_r$q;
        p = p_r$q;
        x = x_r$q;
        d = d_r$q;
        neg = neg_r$q;
    end
    
endmodule // divider$stages$4


module divider$stages$4$d_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$4$d_r


module divider$stages$4$neg_r(d,q,clock);
    
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
          
endmodule // divider$stages$4$neg_r


module divider$stages$4$p_r(d,q,clock);
    
    // Module arguments
    input wire  [33:0] d;
    output reg  [33:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 34'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$4$p_r


module divider$stages$4$valid_r(d,q,clock);
    
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
          
endmodule // divider$stages$4$valid_r


module divider$stages$4$x_r(d,q,clock);
    
    // Module arguments
    input wire  [24:0] d;
    output reg  [24:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 25'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // divider$stages$4$x_r
